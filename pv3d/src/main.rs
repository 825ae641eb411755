//! `pv3d a.xml b.xml …` — compose Player devices into a 3D viewer.

use std::net::{IpAddr, Ipv4Addr};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use clap::Parser;
use player_proto::client::fan_out;
use player_proto::server::Commanders;
use player_sim::serve::ServeOptions;
use player_web::WebFront;
use pv3d::app::{
    RedrawPolicy, ScreenshotRequest, UiWaker, ViewerBuilder, WindowOptions, run_window,
};
use pv3d::commands::{Grammar, Script};
use pv3d::composition::{Composition, ParserRegistry, emit_document};
use pv3d::embedded_world::serve_world;
use pv3d::headless::{HeadlessRun, ScreenshotRun, run_headless, write_screenshot};
use pv3d::render::Projection;
use pv3d::robots::recording::Recording;
use pv3d::zenoh_robots::{ZenohSource, open_zenoh_robots};

/// Player Viewer 3D: compose Player devices into a 3D viewer and tele-operation tool.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Cli {
    /// Composition files (`<pv3d>` documents or lone `<plugin>` templates), merged in order.
    files: Vec<PathBuf>,

    /// Simulate stage-worlds/multirobot.world in-process and show it with
    /// configs/multirobot.pv3d.xml (or the compositions given): no Player server needed.
    #[arg(long)]
    demo: bool,

    /// Simulate this Stage world (and the .cfg beside it) in-process on free ports and show
    /// it, with the world's own configs/<world>.pv3d.xml if there is one, else
    /// configs/stage-world.pv3d.xml, unless compositions are given.
    #[arg(long, value_name = "WORLD", conflicts_with = "demo")]
    world: Option<PathBuf>,

    /// Open the robots found in Zenoh through this endpoint (a router's or a robot relay's,
    /// e.g. tcp/10.0.0.1:7447; repeatable): each is served on a free loopback port, as
    /// `player-relay --from-zenoh` does, and shown with configs/stage-world.pv3d.xml unless
    /// compositions are given.
    #[arg(long, value_name = "ENDPOINT", conflicts_with_all = ["demo", "world"])]
    zenoh: Vec<String>,

    /// With --zenoh: the site whose robots are opened (every site by default).
    #[arg(long, value_name = "NAME", default_value = "*", requires = "zenoh")]
    zenoh_site: String,

    /// With --zenoh: the identity sent with commands; the robots' relays execute those of
    /// their `--zenoh-controller` only (default: this Zenoh session's id).
    #[arg(long, value_name = "ID", requires = "zenoh")]
    zenoh_id: Option<String>,

    /// With --zenoh: Zenoh's own JSON5 configuration file, amended by the endpoints.
    #[arg(long, value_name = "FILE", requires = "zenoh")]
    zenoh_config: Option<PathBuf>,

    /// Record every message of every server to this file (docs/RECORDING-FORMAT.md): MCAP,
    /// with Foxglove's schemas, when it is named `*.mcap`; replay it with `player-sim --replay
    /// FILE`.
    #[arg(long, value_name = "FILE.prec|FILE.mcap")]
    record: Option<PathBuf>,

    /// Simulated seconds per real second for --demo and --world.
    #[arg(long, default_value_t = 1.0, value_name = "FACTOR")]
    speedup: f64,

    /// Write the composition the handlers produced to this file and exit.
    #[arg(long, value_name = "OUT.xml")]
    emit_config: Option<PathBuf>,

    /// Run the composition, wait `--after` seconds, write the window to this PNG and exit.
    #[arg(long, value_name = "OUT.png")]
    screenshot: Option<PathBuf>,

    /// Seconds to run before taking the screenshot.
    #[arg(long, default_value_t = 2.0, value_name = "SECONDS")]
    after: f64,

    /// Run offscreen (no window, no X server needed): with --screenshot, to take it; alone, to
    /// record, run a script or measure until --quit-after. Implied by --screenshot when no
    /// DISPLAY is set.
    #[arg(long)]
    headless: bool,

    /// Window size, WIDTHxHEIGHT.
    #[arg(long, default_value = "1280x800", value_parser = parse_size)]
    size: (u32, u32),

    /// Redraw at most this often while data arrives, in seconds.
    #[arg(long, default_value_t = 0.10, value_name = "SECONDS")]
    redraw_interval: f64,

    /// Redraw continuously instead of only when something changed.
    #[arg(long)]
    redraw_when_idle: bool,

    /// Write the composition with the plugins' current state here on exit and on "Save".
    #[arg(long, value_name = "OUT.xml")]
    save_to: Option<PathBuf>,

    /// Close the window (or end a --headless run) after this many seconds (for scripted runs,
    /// recordings and measurements).
    #[arg(long, value_name = "SECONDS")]
    quit_after: Option<f64>,

    /// On exit, print how many frames the window drew (to check the redraw policy).
    #[arg(long)]
    frame_stats: bool,

    /// Seconds to wait for the Player servers' device lists before building the scene (and,
    /// with --zenoh, for the first robot to be found).
    #[arg(long, default_value_t = 3.0, value_name = "SECONDS")]
    connect_timeout: f64,

    /// Watch only: the clients are read-only (no command or configuration request is ever
    /// sent) and the viewer offers no tele-operation, targets or click-to-go.
    #[arg(long)]
    observe: bool,

    /// Say these sentences to the viewer, one `<seconds> <sentence>` a line ("3 robot1 go to
    /// charging"), seconds counted from when the viewer starts running.
    #[arg(long, value_name = "FILE")]
    script: Option<PathBuf>,

    /// Parse sentences with this grammar instead of the built-in configs/commands.grammar.xml.
    #[arg(long, value_name = "FILE.xml")]
    grammar: Option<PathBuf>,

    /// Also serve a live web page of these robots on this port, on every interface: anyone on
    /// the network opens `http://this-host:PORT/` in a browser, nothing to install. Read-only:
    /// the robots are driven from this viewer.
    #[arg(long, value_name = "PORT")]
    serve_web: Option<u16>,

    /// The view to start in: the map-like top view or the perspective one (T switches).
    #[arg(long, value_enum, default_value_t = StartView::Top)]
    view: StartView,
}

/// The projection the 3D view starts in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum StartView {
    Top,
    Perspective,
}

fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let (w, h) = text
        .split_once('x')
        .ok_or("expected WIDTHxHEIGHT, e.g. 1280x800")?;
    let w: u32 = w.parse().map_err(|_| format!("bad width {w:?}"))?;
    let h: u32 = h.parse().map_err(|_| format!("bad height {h:?}"))?;
    if !(64..=8192).contains(&w) || !(64..=8192).contains(&h) {
        return Err("width and height must be from 64 to 8192".into());
    }
    Ok((w, h))
}

/// The read-only page of `--serve-web`, on every interface.
fn serve_web(port: u16) -> Result<WebFront> {
    let any = IpAddr::V4(Ipv4Addr::UNSPECIFIED);
    let web = WebFront::start(any, port, Commanders::Nobody)?;
    eprintln!(
        "serving the web page of these robots on port {0}: http://localhost:{0}/ here, \
         http://<this host>:{0}/ elsewhere",
        web.port()
    );
    Ok(web)
}

fn main() -> ExitCode {
    // `--frame-stats` counts the first whole picture from here: a world's start-up included.
    let process_started = Instant::now();
    program_edge::logging::init("info");
    program_edge::exit::exit_code("pv3d", run(Cli::parse(), process_started))
}

fn run(mut cli: Cli, process_started: Instant) -> Result<()> {
    if cli.demo {
        cli.world = Some(pv3d::demo::world_file());
        if cli.files.is_empty() {
            cli.files.push(pv3d::demo::composition_file());
        }
    }
    if let Some(world) = cli.world.as_deref().filter(|_| cli.files.is_empty()) {
        cli.files.push(pv3d::demo::world_composition_file(world));
    }
    if !cli.zenoh.is_empty() && cli.files.is_empty() {
        cli.files.push(pv3d::demo::any_robots_composition_file());
    }
    if !(0.0..=1000.0).contains(&cli.speedup) {
        bail!("--speedup must be from 0 (as fast as possible) to 1000");
    }
    if cli.files.is_empty() {
        bail!("no composition given: try `pv3d --demo` or `pv3d configs/single-laser.pv3d.xml`");
    }
    if !(0.001..=10.0).contains(&cli.redraw_interval) {
        bail!("--redraw-interval must be from 0.001 to 10 seconds");
    }
    if cli.quit_after.is_some_and(|s| !(0.0..=1e6).contains(&s)) {
        bail!("--quit-after must be from 0 to 1000000 seconds");
    }
    if !(0.0..=60.0).contains(&cli.connect_timeout) {
        bail!("--connect-timeout must be from 0 to 60 seconds");
    }
    if !(0.0..=1e6).contains(&cli.after) {
        bail!("--after must be from 0 to 1000000 seconds");
    }
    let no_display =
        std::env::var_os("DISPLAY").is_none() && std::env::var_os("WAYLAND_DISPLAY").is_none();
    if no_display && !cli.headless && cli.screenshot.is_none() && cli.emit_config.is_none() {
        bail!(
            "no display to open a window on (neither DISPLAY nor WAYLAND_DISPLAY is set): run \
             pv3d on a desktop, under `xvfb-run`, add `--screenshot out.png` to render \
             offscreen, or `--headless` to run without drawing a window (with --record, \
             --script, --quit-after)"
        );
    }

    // Read before anything starts, so that a mistake in them is reported at once.
    let script = cli.script.as_deref().map(Script::load).transpose()?;
    let grammar = cli.grammar.as_deref().map(Grammar::load).transpose()?;

    let parsers = ParserRegistry::standard();
    let mut composition = Composition::load_files(&cli.files, &parsers)?;
    // Kept alive for as long as the viewer runs.
    let _world = match &cli.world {
        Some(world) => {
            let options = ServeOptions {
                speedup: cli.speedup,
                ..ServeOptions::default()
            };
            Some(serve_world(world, &mut composition, options)?)
        }
        None => None,
    };
    let _zenoh = match cli.zenoh.is_empty() {
        false => {
            let source = ZenohSource {
                connect: cli.zenoh.clone(),
                config_file: cli.zenoh_config.clone(),
                site: cli.zenoh_site.clone(),
                identity: cli.zenoh_id.clone(),
            };
            let wait = Duration::from_secs_f64(cli.connect_timeout);
            Some(open_zenoh_robots(&source, &mut composition, wait)?)
        }
        true => None,
    };
    let waker = UiWaker::default();
    // Declared before the viewer, so dropped after it: the robots hold their taps.
    let recording = cli.record.as_deref().map(Recording::start).transpose()?;
    let web = cli.serve_web.map(serve_web).transpose()?;
    let taps = (recording.iter().map(Recording::tap))
        .chain(web.iter().map(WebFront::tap))
        .collect();
    let mut builder = ViewerBuilder::new(composition)
        .wake_with(waker.notifier())
        .connect_timeout(Duration::from_secs_f64(cli.connect_timeout))
        .observe(cli.observe)
        .record_with(fan_out(taps))
        .start_view(match cli.view {
            StartView::Top => Projection::Top,
            StartView::Perspective => Projection::Perspective,
        });
    if let Some(path) = &cli.save_to {
        builder = builder.save_to(path.clone());
    }
    let parts = builder.connect();
    for client in parts.clients() {
        web.iter().for_each(|web| web.add_robot(client.clone()));
    }

    if let Some(out) = &cli.emit_config {
        let written = parts.written_instances();
        std::fs::write(out, emit_document(parts.composition(), &written, out))
            .with_context(|| format!("writing {}", out.display()))?;
        eprintln!("wrote {} ({} plugins)", out.display(), written.len());
        return Ok(());
    }

    let mut viewer = parts.into_viewer();
    if let Some(grammar) = grammar {
        viewer.set_grammar(grammar);
    }
    if let Some(script) = script {
        viewer.run_script(script);
    }
    let interval = Duration::from_secs_f64(cli.redraw_interval);
    let after = Duration::from_secs_f64(cli.after);
    match &cli.screenshot {
        Some(path) if cli.headless || no_display => {
            let started = Instant::now();
            let run = ScreenshotRun {
                size: cli.size,
                after,
                interval,
            };
            write_screenshot(&mut viewer, &run, path)?;
            eprintln!(
                "wrote {} after {:.1} s",
                path.display(),
                started.elapsed().as_secs_f64()
            );
            Ok(())
        }
        None if cli.headless => {
            let run = HeadlessRun {
                counted_from: process_started,
                size: cli.size,
                interval,
                quit_after: cli.quit_after.map(Duration::from_secs_f64),
            };
            let summary = run_headless(&mut viewer, &run)?;
            if cli.frame_stats {
                eprintln!("{}", summary.frames.stats(Instant::now()));
            }
            Ok(())
        }
        _ => {
            let options = WindowOptions {
                title: "pv3d".into(),
                size: cli.size,
                policy: if cli.redraw_when_idle {
                    RedrawPolicy::WhenIdle
                } else {
                    RedrawPolicy::OnChange { interval }
                },
                screenshot: cli
                    .screenshot
                    .clone()
                    .map(|path| ScreenshotRequest { path, after }),
                quit_after: cli.quit_after.map(Duration::from_secs_f64),
                frame_stats: cli.frame_stats,
                counted_from: process_started,
            };
            run_window(viewer, options, waker).map_err(anyhow::Error::msg)
        }
    }
}

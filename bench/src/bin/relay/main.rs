//! The relay benchmark: 8 robot servers, 1 000 observers connected straight to them, then the
//! same 1 000 through `player-relay`, in one run.
//!
//! ```sh
//! cargo run --release -p bench --bin relay
//! cargo run --release -p bench --bin relay -- --zenoh     # and through Zenoh, 4 remote bridges
//! cargo build --release -p player-relay && \
//!   cargo run --release -p bench --bin relay -- --swarm stage-worlds/swarm1024.world
//!                                          # the fronts at 1 024 robots, real page and Foxglove
//! ```
//!
//! The robots and the relay are child processes (this binary again, with `--role`), so that
//! the CPU time and resident memory of each are its own; the observers are async tasks in this
//! process ([`bench::observers`]). Every DATA message carries its publish time (Unix seconds,
//! the clock the processes share) in its header, and latency is taken where an observer
//! decodes it. The children stop when this process closes their standard input, whatever
//! ends it. Loopback only.

mod faults;
mod fronts;
mod roles;
mod swarm;
mod uplink;
mod viewers;
mod zenoh;
mod zenoh_roles;

use std::time::Duration;

use anyhow::{Result, bail};
use bench::clock::{SharedWindow, unix_seconds};
use bench::observers::connect_observers;
use bench::process_stats::ProcessSample;
use bench::recorder::LatencySummary;
use bench::traffic::DEVICES;
use clap::{Parser, ValueEnum};
use roles::RoleProcess;

/// How long observers and relay may take to come up before the run is called off.
pub(crate) const SETUP_TIMEOUT: Duration = Duration::from_secs(60);
/// Time after the window closes for messages sent inside it to arrive.
pub(crate) const DRAIN: Duration = Duration::from_millis(500);

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Role {
    Orchestrator,
    Robots,
    Relay,
    ZenohRouter,
    ZenohSite,
    ZenohBridge,
}

#[derive(Parser, Debug)]
#[command(about = "1 000 observers of 8 robots: straight to the servers vs through player-relay")]
pub(crate) struct Args {
    #[arg(long, value_enum, default_value_t = Role::Orchestrator, hide = true)]
    pub(crate) role: Role,
    /// Upstream ports, for the relay role.
    #[arg(long, value_delimiter = ',', hide = true)]
    pub(crate) upstream: Vec<u16>,
    /// Listening ports, for the relay role (default: any free ones).
    #[arg(long, value_delimiter = ',', hide = true)]
    pub(crate) listen: Vec<u16>,
    /// Instead of the load phases: kill the relay mid-stream and let observers vanish.
    #[arg(long)]
    pub(crate) faults: bool,
    /// Instead of the load phases: the relay's fronts (web pages, Foxglove clients) under
    /// load, against one direct Player observer per robot (for the relay role: start them).
    #[arg(long)]
    pub(crate) fronts: bool,
    /// Web pages, with --fronts.
    #[arg(long, default_value_t = 200)]
    pub(crate) pages: usize,
    /// Foxglove clients, with --fronts.
    #[arg(long, default_value_t = 200)]
    pub(crate) foxglove_clients: usize,
    /// Instead of the load phases: `player-relay --world WORLD --web --foxglove` idle, with one
    /// real page, one real Foxglove client, and both (see `swarm`).
    #[arg(long, value_name = "WORLD")]
    pub(crate) swarm: Option<std::path::PathBuf>,
    /// With --swarm: the relay binaries to measure in turn (default: the one built beside
    /// this benchmark).
    #[arg(long, value_name = "PATH")]
    pub(crate) relay_binary: Vec<std::path::PathBuf>,
    /// With --swarm: seconds for the relay to reach its robots before anything is measured.
    #[arg(long, default_value_t = 30.0)]
    pub(crate) settle: f64,
    /// With --swarm: the channels the Foxglove client subscribes to (a regular expression
    /// over topics): by default every robot's pose and eight robots' scans.
    #[arg(
        long,
        default_value = r"^/[^/]+/position2d/0/pose$|^/s[0-7]/laser/0/scan$"
    )]
    pub(crate) foxglove_topics: String,
    /// Instead of the load phases: direct, player-relay alone, and through a Zenoh router to
    /// `--bridges` remote processes serving the robots as Player servers.
    #[arg(long)]
    pub(crate) zenoh: bool,
    /// Remote bridge processes the observers are spread over, with --zenoh.
    #[arg(long, default_value_t = 4)]
    pub(crate) bridges: usize,
    /// The Zenoh router's port (or the site's way to it), for the Zenoh roles.
    #[arg(long, default_value_t = 0, hide = true)]
    pub(crate) router: u16,
    #[arg(long, default_value_t = 8)]
    pub(crate) robots: usize,
    #[arg(long, default_value_t = 1000)]
    pub(crate) observers: usize,
    /// Laser beams per scan.
    #[arg(long, default_value_t = 361)]
    pub(crate) beams: usize,
    /// Messages per second per device.
    #[arg(long, default_value_t = 10.0)]
    pub(crate) rate_hz: f64,
    /// Receiving before the window opens, seconds.
    #[arg(long, default_value_t = 3.0)]
    pub(crate) warmup: f64,
    /// Measurement window per phase, seconds.
    #[arg(long, default_value_t = 10.0)]
    pub(crate) seconds: f64,
}

fn main() -> Result<()> {
    // The Foxglove SDK logs an error per queued message when a client vanishes (every
    // client does, at the end): not what the figures are about.
    program_edge::logging::init("warn,foxglove::websocket=off");
    let args = Args::parse();
    if args.robots == 0 || args.observers == 0 || args.beams == 0 {
        bail!("--robots, --observers and --beams must be positive");
    }
    if !(0.1..=1000.0).contains(&args.rate_hz)
        || !(0.0..=600.0).contains(&args.warmup)
        || !(0.1..=600.0).contains(&args.seconds)
    {
        bail!("--rate-hz must be 0.1..1000, --warmup 0..600 and --seconds 0.1..600");
    }
    match args.role {
        Role::Robots => roles::serve_robots(&args),
        Role::Relay => roles::serve_relay(&args),
        Role::ZenohRouter => zenoh_roles::serve_router(),
        Role::ZenohSite => zenoh_roles::serve_site(&args),
        Role::ZenohBridge => zenoh_roles::serve_bridge(&args),
        Role::Orchestrator if args.swarm.is_some() => swarm::run(
            args.swarm.as_deref().unwrap_or(std::path::Path::new("")),
            &args,
        ),
        Role::Orchestrator if args.faults => faults::run(&args),
        Role::Orchestrator if args.fronts => fronts::run(&args),
        Role::Orchestrator if args.zenoh => zenoh::run(&args),
        Role::Orchestrator => orchestrate(&args),
    }
}

/// One phase's figures.
struct Phase {
    name: &'static str,
    latency: Option<LatencySummary>,
    received: usize,
    expected: f64,
    failed: usize,
    /// CPU seconds per second, robots and relay.
    cpu: (f64, f64),
    /// Resident memory gained while the observers were connected, robots and relay.
    rss_gain: (i64, i64),
    /// Connections to the robots (their sockets less their listening ones).
    robot_connections: usize,
}

fn run_phase(
    args: &Args,
    name: &'static str,
    ports: &[u16],
    robots: &RoleProcess,
    relay: &RoleProcess,
) -> Result<Phase> {
    let window = SharedWindow::default();
    let (robots0, relay0) = (robots.sample()?, relay.sample()?);
    let observers = connect_observers(ports, args.observers, window.clone(), SETUP_TIMEOUT)?;
    std::thread::sleep(Duration::from_secs_f64(args.warmup));
    let (robots1, relay1) = (robots.sample()?, relay.sample()?);
    let start = unix_seconds();
    window.set(start, start + args.seconds);
    std::thread::sleep(Duration::from_secs_f64(args.seconds));
    let (robots2, relay2) = (robots.sample()?, relay.sample()?);
    std::thread::sleep(DRAIN);
    let crowd = observers.finish();
    let per_second =
        |a: &ProcessSample, b: &ProcessSample| (b.cpu_seconds - a.cpu_seconds) / args.seconds;
    let gain = |a: &ProcessSample, b: &ProcessSample| b.rss_bytes as i64 - a.rss_bytes as i64;
    Ok(Phase {
        name,
        latency: LatencySummary::of(&crowd.latencies),
        received: crowd.latencies.len(),
        expected: args.observers as f64 * DEVICES.len() as f64 * args.rate_hz * args.seconds,
        failed: crowd.failed,
        cpu: (per_second(&robots1, &robots2), per_second(&relay1, &relay2)),
        rss_gain: (gain(&robots0, &robots2), gain(&relay0, &relay2)),
        robot_connections: robots2.sockets.saturating_sub(args.robots),
    })
}

fn orchestrate(args: &Args) -> Result<()> {
    let robots = RoleProcess::spawn(args, "robots", &[])?;
    let upstream: Vec<String> = robots.ports.iter().map(u16::to_string).collect();
    let relay = RoleProcess::spawn(args, "relay", &["--upstream".into(), upstream.join(",")])?;
    eprintln!(
        "{} robots on {:?}, relayed on {:?}; {} observers per phase",
        args.robots, robots.ports, relay.ports, args.observers
    );
    // Idle: what publishing costs the robots, and the relay with nobody watching.
    let (r0, q0) = (robots.sample()?, relay.sample()?);
    std::thread::sleep(Duration::from_secs_f64(args.seconds));
    let (r1, q1) = (robots.sample()?, relay.sample()?);
    let idle = (
        (r1.cpu_seconds - r0.cpu_seconds) / args.seconds,
        (q1.cpu_seconds - q0.cpu_seconds) / args.seconds,
    );
    let direct = run_phase(args, "direct", &robots.ports, &robots, &relay)?;
    let relayed = run_phase(args, "relay", &relay.ports, &robots, &relay)?;
    print_report(args, idle, &[direct, relayed]);
    Ok(())
}

fn print_report(args: &Args, idle: (f64, f64), phases: &[Phase]) {
    let ms = |s: f64| s * 1e3;
    println!(
        "{} robots (position2d + {}-beam laser at {} Hz), {} observers, {} s window; idle CPU: robots {:.1} %, relay {:.1} %\n",
        args.robots,
        args.beams,
        args.rate_hz,
        args.observers,
        args.seconds,
        idle.0 * 100.0,
        idle.1 * 100.0
    );
    println!(
        "| observers | p50 ms | p99 ms | max ms | received | failed | robots CPU % | relay CPU % | CPU per observer (µs/s) | memory per observer (kB) | connections to robots |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for p in phases {
        let (p50, p99, max) = p.latency.map_or((f64::NAN, f64::NAN, f64::NAN), |l| {
            (ms(l.p50), ms(l.p99), ms(l.max))
        });
        // What serving the observers cost, over publishing alone.
        let serving = (p.cpu.0 - idle.0) + (p.cpu.1 - idle.1);
        let memory = (p.rss_gain.0 + p.rss_gain.1) as f64 / 1024.0 / args.observers as f64;
        println!(
            "| {} | {p50:.2} | {p99:.2} | {max:.1} | {:.1} % | {} | {:.1} | {:.1} | {:.1} | {memory:.1} | {} |",
            p.name,
            100.0 * p.received as f64 / p.expected,
            p.failed,
            p.cpu.0 * 100.0,
            p.cpu.1 * 100.0,
            serving / args.observers as f64 * 1e6,
            p.robot_connections,
        );
    }
    if let [direct, relayed] = phases
        && let (Some(d), Some(r)) = (direct.latency, relayed.latency)
    {
        println!(
            "\nadded by the relay: p50 {:+.2} ms, p99 {:+.2} ms",
            ms(r.p50 - d.p50),
            ms(r.p99 - d.p99)
        );
    }
}

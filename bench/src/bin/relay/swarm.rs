//! `relay --swarm WORLD`: what the fronts cost at a thousand robots. `player-relay --world
//! WORLD --web 0 --foxglove 0` (the robots simulated in the relay's own process, as a user
//! starts it) is measured with nobody watching, then with one real page (Chromium), one real
//! Foxglove client (`@foxglove/ws-protocol`), and both at once: the relay process's CPU (cores)
//! and resident memory over the window, and what the viewers saw (the page's pose rows in Hz,
//! the Foxglove channels' rates). Each `--relay-binary` is measured in turn, in the same run,
//! so that two builds compare on the same machine at the same minutes.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::channel;
use std::time::Duration;

use anyhow::{Context, Result, bail};
use bench::process_stats::ProcessSample;

use crate::Args;
use crate::viewers::Viewer;

/// How long a viewer may take to show everything (Chromium listing a thousand robots).
const VIEWER_READY: Duration = Duration::from_secs(120);

/// The relay under test; killed when dropped.
struct RelayProcess {
    child: Child,
    web: u16,
    foxglove: u16,
}

impl RelayProcess {
    fn start(binary: &Path, world: &Path) -> Result<RelayProcess> {
        let mut child = Command::new(binary)
            .arg("--world")
            .arg(world)
            .args(["--web", "0", "--foxglove", "0"])
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .with_context(|| format!("{} starts", binary.display()))?;
        let stderr = child.stderr.take().context("the relay's stderr")?;
        let (send, ports) = channel();
        // Read to the end: a full pipe would stop the relay.
        std::thread::spawn(move || {
            for line in BufReader::new(stderr).lines().map_while(Result::ok) {
                let port = |after: &str| {
                    let rest = &line[line.find(after)? + after.len()..];
                    let rest = rest.rsplit(':').next()?;
                    rest.trim_end_matches('/').trim().parse::<u16>().ok()
                };
                if line.starts_with("web page: ") {
                    let _ = send.send(("web", port("http://")));
                } else if line.starts_with("Foxglove WebSocket") {
                    let _ = send.send(("foxglove", port("ws://")));
                }
            }
        });
        let (mut web, mut foxglove) = (None, None);
        while web.is_none() || foxglove.is_none() {
            match ports.recv_timeout(Duration::from_secs(120)) {
                Ok(("web", port)) => web = port,
                Ok((_, port)) => foxglove = port,
                Err(e) => bail!("the relay never said its fronts' ports: {e}"),
            }
        }
        Ok(RelayProcess {
            child,
            web: web.unwrap_or_default(),
            foxglove: foxglove.unwrap_or_default(),
        })
    }

    fn sample(&self) -> Result<ProcessSample> {
        Ok(ProcessSample::take(self.child.id())?)
    }
}

impl Drop for RelayProcess {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// One phase: the relay's cores and memory over the window, and what the viewers said.
struct Phase {
    name: &'static str,
    cores: f64,
    rss_mib: f64,
    seen: Vec<String>,
}

fn phase(
    relay: &RelayProcess,
    args: &Args,
    name: &'static str,
    page: bool,
    foxglove: bool,
) -> Result<Phase> {
    // The viewers count a little longer than the window, which lies inside their count.
    let counting = (args.seconds + 2.0).to_string();
    let mut viewers = Vec::new();
    if page {
        let url = format!("http://127.0.0.1:{}/", relay.web);
        let args = ["watch".to_string(), url, counting.clone()];
        viewers.push(("page", Viewer::start("page.mjs", &args)?));
    }
    if foxglove {
        let url = format!("ws://127.0.0.1:{}", relay.foxglove);
        let args = [
            "watch".to_string(),
            url,
            args.foxglove_topics.clone(),
            counting.clone(),
            (VIEWER_READY.as_millis()).to_string(),
        ];
        viewers.push(("Foxglove", Viewer::start("foxglove_client.mjs", &args)?));
    }
    // A viewer that never shows everything (the relay before watching could not list a
    // thousand robots on a loaded machine) is said in the row; the relay is measured anyway.
    let mut seen = Vec::new();
    let mut watching = Vec::new();
    for (what, viewer) in viewers {
        match viewer.watching(VIEWER_READY) {
            Ok(()) => watching.push((what, viewer)),
            Err(e) => seen.push(format!("{what}: did not show every robot ({e})")),
        }
    }
    std::thread::sleep(Duration::from_secs(1));
    let before = relay.sample()?;
    std::thread::sleep(Duration::from_secs_f64(args.seconds));
    let after = relay.sample()?;
    for (what, viewer) in watching {
        match viewer.finish(Duration::from_secs_f64(args.seconds + 30.0)) {
            Ok(saw) => seen.push(format!("{what}: {saw}")),
            Err(e) => seen.push(format!("{what}: {e}")),
        }
    }
    Ok(Phase {
        name,
        cores: (after.cpu_seconds - before.cpu_seconds) / args.seconds,
        rss_mib: after.rss_bytes as f64 / 1048576.0,
        seen,
    })
}

fn measure(binary: &Path, world: &Path, args: &Args) -> Result<Vec<Phase>> {
    let relay = RelayProcess::start(binary, world)?;
    eprintln!(
        "{}: page on {}, Foxglove on {}; settling {} s",
        binary.display(),
        relay.web,
        relay.foxglove,
        args.settle
    );
    std::thread::sleep(Duration::from_secs_f64(args.settle));
    let idle0 = relay.sample()?;
    std::thread::sleep(Duration::from_secs_f64(args.seconds));
    let idle1 = relay.sample()?;
    let mut phases = vec![Phase {
        name: "nobody watching",
        cores: (idle1.cpu_seconds - idle0.cpu_seconds) / args.seconds,
        rss_mib: idle1.rss_bytes as f64 / 1048576.0,
        seen: Vec::new(),
    }];
    for (name, page, foxglove) in [
        ("one page", true, false),
        ("one Foxglove client", false, true),
        ("one page + one Foxglove client", true, true),
    ] {
        phases.push(phase(&relay, args, name, page, foxglove)?);
        // What the viewers looked at is let go before the next phase measures.
        std::thread::sleep(Duration::from_secs(3));
    }
    Ok(phases)
}

/// The relay built beside this benchmark.
fn built_relay() -> Result<PathBuf> {
    let me = std::env::current_exe()?;
    Ok(me.with_file_name("player-relay"))
}

pub fn run(world: &Path, args: &Args) -> Result<()> {
    let binaries = match args.relay_binary.is_empty() {
        true => vec![built_relay()?],
        false => args.relay_binary.clone(),
    };
    let mut results = Vec::new();
    for binary in &binaries {
        results.push((binary, measure(binary, world, args)?));
    }
    println!(
        "{} through `player-relay --world … --web 0 --foxglove 0`, {} s windows; Foxglove topics {}\n",
        world.display(),
        args.seconds,
        args.foxglove_topics
    );
    println!("| relay | phase | relay CPU (cores) | relay RSS (MiB) | the viewers saw |");
    println!("|---|---|---:|---:|---|");
    for (binary, phases) in &results {
        for p in phases {
            println!(
                "| {} | {} | {:.2} | {:.0} | {} |",
                binary.display(),
                p.name,
                p.cores,
                p.rss_mib,
                p.seen.join("; ")
            );
        }
    }
    Ok(())
}

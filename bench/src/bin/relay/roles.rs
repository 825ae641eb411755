//! The benchmark's other processes: the robots and the relay, each this binary again with
//! `--role`, telling the orchestrator their ports on standard output and stopping when their
//! standard input closes.

use std::io::{BufRead, BufReader, Write};
use std::process::{Child, ChildStdout, Command, Stdio};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use anyhow::{Context, Result, bail};
use bench::clock::unix_seconds;
use bench::process_stats::ProcessSample;
use bench::traffic::{DEVICES, PUBLISHED, bodies};
use player_foxglove::live::FoxgloveLive;
use player_proto::server::Commanders;
use player_proto::server::{Server, ServerConfig};
use player_proto::wire::DevAddr;
use player_relay::{Relay, RelayConfig, Route};
use player_web::WebFront;

const LOCALHOST: std::net::IpAddr = std::net::IpAddr::V4(std::net::Ipv4Addr::LOCALHOST);

use crate::{Args, SETUP_TIMEOUT};

/// Prints the ports on a line of their own for the orchestrator.
pub(crate) fn announce(ports: &[u16]) -> Result<()> {
    let list: Vec<String> = ports.iter().map(u16::to_string).collect();
    let mut out = std::io::stdout().lock();
    writeln!(out, "PORTS {}", list.join(","))?;
    out.flush()?;
    Ok(())
}

/// Blocks until the orchestrator closes our standard input (or goes away).
pub(crate) fn until_stdin_closes() {
    let mut sink = String::new();
    while std::io::stdin().read_line(&mut sink).is_ok_and(|n| n > 0) {
        sink.clear();
    }
}

pub fn serve_robots(args: &Args) -> Result<()> {
    let mut config = ServerConfig::default();
    config.thread_name = "bench-robots".into();
    for _ in 0..args.robots {
        let robot = config.robot(0);
        for interf in DEVICES {
            config.device(robot, DevAddr::local(interf, 0), Publishing);
        }
    }
    let server = Server::start(config)?;
    let ports = server.ports().to_vec();
    let stop = Arc::new(AtomicBool::new(false));
    let generator = {
        let (publisher, stop, ports) = (server.publisher(), stop.clone(), ports.clone());
        let (bodies, rate) = (bodies(args.beams), args.rate_hz);
        std::thread::Builder::new()
            .name("bench-traffic".into())
            .spawn(move || {
                // Robots staggered evenly over the period, as independent robots are.
                let slot = 1.0 / rate / ports.len() as f64;
                let start = unix_seconds();
                let mut event = 0u64;
                while !stop.load(Ordering::Relaxed) {
                    let due = start + event as f64 * slot;
                    let now = unix_seconds();
                    if due > now {
                        std::thread::sleep(Duration::from_secs_f64(due - now));
                        continue;
                    }
                    let port = ports[(event % ports.len() as u64) as usize];
                    for (kind, body) in PUBLISHED.iter().zip(&bodies) {
                        let mut addr = DevAddr::local(kind.interf, 0);
                        addr.robot = u32::from(port);
                        publisher.publish(addr, kind.subtype, body.clone(), unix_seconds());
                    }
                    event += 1;
                }
            })?
    };
    announce(&ports)?;
    until_stdin_closes();
    stop.store(true, Ordering::Relaxed);
    let _ = generator.join();
    Ok(())
}

/// A device that only publishes.
struct Publishing;

impl player_proto::server::Device for Publishing {
    fn driver_name(&self) -> &str {
        "bench"
    }
}

pub fn serve_relay(args: &Args) -> Result<()> {
    let routes = args
        .upstream
        .iter()
        .enumerate()
        .map(|(i, &port)| Route {
            listen_port: args.listen.get(i).copied().unwrap_or(0),
            ..Route::loopback(port)
        })
        .collect();
    // The fronts share one runtime, as player-relay's do.
    let runtime = player_front::shared_runtime()?;
    let (web, foxglove) = if args.fronts {
        let handle = runtime.handle();
        (
            Some(Arc::new(WebFront::start_on(
                handle.clone(),
                LOCALHOST,
                0,
                Commanders::Nobody,
            )?)),
            Some(Arc::new(FoxgloveLive::start_on(
                handle.clone(),
                LOCALHOST,
                0,
            )?)),
        )
    } else {
        (None, None)
    };
    let mut fronts: Vec<Arc<dyn player_relay::Front>> = Vec::new();
    fronts.extend(web.iter().map(|w| w.clone() as _));
    fronts.extend(foxglove.iter().map(|f| f.clone() as _));
    let relay = Relay::start(RelayConfig {
        routes,
        fronts,
        ..RelayConfig::default()
    })?;
    let serving = relay.wait_serving(SETUP_TIMEOUT);
    if serving != args.upstream.len() {
        bail!(
            "the relay serves {serving} of {} robots",
            args.upstream.len()
        );
    }
    let mut ports: Vec<u16> = relay
        .robots()
        .iter()
        .filter_map(|r| r.listen_port())
        .collect();
    // The fronts' ports follow the robots'.
    ports.extend(web.as_ref().map(|w| w.port()));
    ports.extend(foxglove.as_ref().map(|f| f.port()));
    announce(&ports)?;
    until_stdin_closes();
    Ok(())
}

/// A child process of this binary in another role.
pub struct RoleProcess {
    pub child: Child,
    pub ports: Vec<u16>,
}

impl RoleProcess {
    pub fn spawn(args: &Args, role: &str, extra: &[String]) -> Result<RoleProcess> {
        let mut child = Command::new(std::env::current_exe()?)
            .args(["--role", role])
            .args(["--robots", &args.robots.to_string()])
            .args(["--beams", &args.beams.to_string()])
            .args(["--rate-hz", &args.rate_hz.to_string()])
            .args(args.fronts.then_some("--fronts"))
            .args(extra)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .with_context(|| format!("starting the {role} process"))?;
        let stdout: ChildStdout = child.stdout.take().context("child stdout")?;
        let mut line = String::new();
        BufReader::new(stdout).read_line(&mut line)?;
        let ports = line
            .trim()
            .strip_prefix("PORTS ")
            .with_context(|| format!("the {role} process said {line:?}"))?
            .split(',')
            .map(str::parse)
            .collect::<Result<Vec<u16>, _>>()?;
        Ok(RoleProcess { child, ports })
    }

    pub fn sample(&self) -> Result<ProcessSample> {
        Ok(ProcessSample::take(self.child.id())?)
    }
}

impl Drop for RoleProcess {
    fn drop(&mut self) {
        drop(self.child.stdin.take());
        let _ = self.child.wait();
    }
}

//! The relay benchmark: 8 robot servers, 1 000 observers connected straight to them, then the
//! same 1 000 through `player-relay`, in one run.
//!
//! ```sh
//! cargo run --release -p bench --bin relay
//! ```
//!
//! The robots and the relay are child processes (this binary again, with `--role`), so that
//! the CPU time and resident memory of each are its own; the observers are async tasks in this
//! process ([`bench::observers`]). Every DATA message carries its publish time (Unix seconds,
//! the clock the processes share) in its header, and latency is taken where an observer
//! decodes it. The children stop when this process closes their standard input, whatever
//! ends it. Loopback only.

use std::io::{BufRead, BufReader, Write};
use std::process::{Child, ChildStdout, Command, Stdio};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use anyhow::{Context, Result, bail};
use bench::clock::{SharedWindow, unix_seconds};
use bench::observers::Observers;
use bench::process_stats::ProcessSample;
use bench::recorder::LatencySummary;
use bench::traffic::{DATA_SUBTYPE, DEVICES, bodies};
use clap::{Parser, ValueEnum};
use player_proto::server::{Server, ServerConfig};
use player_proto::wire::DevAddr;
use player_relay::{Relay, RelayConfig, Route};

/// How long observers and relay may take to come up before the run is called off.
const SETUP_TIMEOUT: Duration = Duration::from_secs(60);
/// Time after the window closes for messages sent inside it to arrive.
const DRAIN: Duration = Duration::from_millis(500);

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Role {
    Orchestrator,
    Robots,
    Relay,
}

#[derive(Parser, Debug)]
#[command(about = "1 000 observers of 8 robots: straight to the servers vs through player-relay")]
struct Args {
    #[arg(long, value_enum, default_value_t = Role::Orchestrator, hide = true)]
    role: Role,
    /// Upstream ports, for the relay role.
    #[arg(long, value_delimiter = ',', hide = true)]
    upstream: Vec<u16>,
    #[arg(long, default_value_t = 8)]
    robots: usize,
    #[arg(long, default_value_t = 1000)]
    observers: usize,
    /// Laser beams per scan.
    #[arg(long, default_value_t = 361)]
    beams: usize,
    /// Messages per second per device.
    #[arg(long, default_value_t = 10.0)]
    rate_hz: f64,
    /// Receiving before the window opens, seconds.
    #[arg(long, default_value_t = 3.0)]
    warmup: f64,
    /// Measurement window per phase, seconds.
    #[arg(long, default_value_t = 10.0)]
    seconds: f64,
}

fn main() -> Result<()> {
    player_tools::logging::init("warn");
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
        Role::Robots => serve_robots(&args),
        Role::Relay => serve_relay(&args),
        Role::Orchestrator => orchestrate(&args),
    }
}

/// Prints the ports on a line of their own for the orchestrator.
fn announce(ports: &[u16]) -> Result<()> {
    let list: Vec<String> = ports.iter().map(u16::to_string).collect();
    let mut out = std::io::stdout().lock();
    writeln!(out, "PORTS {}", list.join(","))?;
    out.flush()?;
    Ok(())
}

/// Blocks until the orchestrator closes our standard input (or goes away).
fn until_stdin_closes() {
    let mut sink = String::new();
    while std::io::stdin().read_line(&mut sink).is_ok_and(|n| n > 0) {
        sink.clear();
    }
}

fn serve_robots(args: &Args) -> Result<()> {
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
                    for (interf, body) in DEVICES.iter().zip(&bodies) {
                        let mut addr = DevAddr::local(*interf, 0);
                        addr.robot = u32::from(port);
                        publisher.publish(addr, DATA_SUBTYPE, body.clone(), unix_seconds());
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

fn serve_relay(args: &Args) -> Result<()> {
    let routes = args
        .upstream
        .iter()
        .map(|&port| Route {
            host: "127.0.0.1".into(),
            port,
            listen_port: 0,
        })
        .collect();
    let relay = Relay::start(RelayConfig {
        routes,
        ..RelayConfig::default()
    })?;
    let serving = relay.wait_serving(SETUP_TIMEOUT);
    if serving != args.upstream.len() {
        bail!(
            "the relay serves {serving} of {} robots",
            args.upstream.len()
        );
    }
    let ports: Vec<u16> = relay
        .robots()
        .iter()
        .filter_map(|r| r.listen_port())
        .collect();
    announce(&ports)?;
    until_stdin_closes();
    Ok(())
}

/// A child process of this binary in another role.
struct RoleProcess {
    child: Child,
    ports: Vec<u16>,
}

impl RoleProcess {
    fn spawn(args: &Args, role: &str, extra: &[String]) -> Result<RoleProcess> {
        let mut child = Command::new(std::env::current_exe()?)
            .args(["--role", role])
            .args(["--robots", &args.robots.to_string()])
            .args(["--beams", &args.beams.to_string()])
            .args(["--rate-hz", &args.rate_hz.to_string()])
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

    fn sample(&self) -> Result<ProcessSample> {
        Ok(ProcessSample::take(self.child.id())?)
    }
}

impl Drop for RoleProcess {
    fn drop(&mut self) {
        drop(self.child.stdin.take());
        let _ = self.child.wait();
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
    let observers = Observers::connect(ports, args.observers, window.clone(), SETUP_TIMEOUT)?;
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

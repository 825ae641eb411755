//! 64 robots to ROS 2: what `player-ros2` costs and how late its messages are. player-sim
//! serves swarm.world (181-beam lasers and odometry at 10 Hz); the first N robots are read,
//! in the same run, first by a Player client alone (the baseline: the client work any bridge
//! does), then through `player-ros2` to a ROS 2 node of the bench's own (ros2-client over
//! RustDDS, on its own participant). Reports each process's cores over the window, their
//! ratio, the scans per second ROS 2 received, and each scan's delay from its arrival at a
//! Player client of the bench's to its arrival in ROS 2 (p50, p99).
//!
//! DDS discovers by multicast: the bench runs itself in a network namespace of its own
//! (`unshare -n`, loopback only, multicast on `lo`), so it needs root.
//!
//! `cargo build --release -p player-sim -p player-ros2 -p bench --bin ros2_bridge`
//! `./target/release/ros2_bridge --robots 64 --seconds 20`

use std::collections::HashMap;
use std::path::PathBuf;
use std::process::{Child, Command};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, ensure};
use bench::process_stats::ProcessSample;
use clap::Parser;
use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::laser::Laser;
use player_proto::message::Body;
use player_proto::wire::{DevAddr, Interface};
use player_ros2::convert::MAPPED;
use player_ros2::msgs::{LaserScan, Time};
use ros2_client::qos::{Durability, History, Reliability};
use ros2_client::{
    Context as RosContext, MessageTypeName, Name, NodeName, NodeOptions, QosProfile,
};

const IN_NAMESPACE: &str = "PLAYER_BENCH_IN_NETNS";
const PORT_BASE: u16 = 21000;
const WARM_UP: Duration = Duration::from_secs(6);

#[derive(Parser, Debug)]
#[command(about = "player-ros2's cost and latency, N robots to ROS 2")]
struct Cli {
    #[arg(long, default_value_t = 64)]
    robots: u16,
    /// Length of each measuring window.
    #[arg(long, default_value_t = 20.0)]
    seconds: f64,
    /// Be the baseline: a Player client of the robots, reading as the bridge does.
    #[arg(long, hide = true)]
    client_only: bool,
}

fn release_binary(name: &str) -> Result<PathBuf> {
    let path = std::env::current_exe()?
        .parent()
        .context("the bench's folder")?
        .join(name);
    ensure!(
        path.is_file(),
        "no {}: cargo build --release -p {name}",
        path.display()
    );
    Ok(path)
}

fn main() -> Result<()> {
    let cli = Cli::parse();
    if cli.client_only {
        return client_only(cli.robots);
    }
    if std::env::var_os(IN_NAMESPACE).is_none() {
        let status = Command::new("unshare")
            .arg("-n")
            .arg(std::env::current_exe()?)
            .args(std::env::args_os().skip(1))
            .env(IN_NAMESPACE, "1")
            .status()
            .context("unshare -n (the bench needs root for a network namespace)")?;
        std::process::exit(status.code().unwrap_or(1));
    }
    for args in [
        &["link", "set", "lo", "up"][..],
        &["link", "set", "lo", "multicast", "on"],
        &["route", "add", "224.0.0.0/4", "dev", "lo"],
    ] {
        ensure!(
            Command::new("ip").args(args).status()?.success(),
            "ip {args:?}"
        );
    }
    let world = std::path::absolute("stage-worlds/swarm.world")?;
    let mut sim = Command::new(release_binary("player-sim")?)
        .arg(&world)
        .args(["--port-base", &PORT_BASE.to_string()])
        .stderr(std::process::Stdio::null())
        .spawn()?;
    let result = measure(&cli);
    let _ = sim.kill();
    let _ = sim.wait();
    result
}

fn robots(n: u16) -> impl Iterator<Item = (u16, String)> {
    (0..n).map(|i| (PORT_BASE + i, format!("s{i}")))
}

/// Cores a child used over `window`, after `warm_up`.
fn cores(child: &Child, warm_up: Duration, window: Duration) -> Result<f64> {
    std::thread::sleep(warm_up);
    let before = ProcessSample::take(child.id())?;
    std::thread::sleep(window);
    let after = ProcessSample::take(child.id())?;
    Ok((after.cpu_seconds - before.cpu_seconds) / window.as_secs_f64())
}

fn measure(cli: &Cli) -> Result<()> {
    let window = Duration::from_secs_f64(cli.seconds);
    wait_for_robots(cli.robots)?;
    println!(
        "{} robots of swarm.world (181-beam laser and odometry at 10 Hz), {} s windows",
        cli.robots, cli.seconds
    );
    let mut baseline = Command::new(std::env::current_exe()?)
        .args(["--client-only", "--robots", &cli.robots.to_string()])
        .spawn()?;
    let client_cores = cores(&baseline, WARM_UP, window);
    let _ = baseline.kill();
    let _ = baseline.wait();
    let client_cores = client_cores?;
    println!("  Player client alone:   {client_cores:.3} cores");

    let robots_arg: Vec<String> = robots(cli.robots)
        .map(|(port, name)| format!("127.0.0.1:{port}={name}"))
        .collect();
    let mut bridge = Command::new(release_binary("player-ros2")?)
        .args(&robots_arg)
        .arg("--read-only")
        .stderr(std::process::Stdio::null())
        .spawn()?;
    let watcher = Watcher::start(cli.robots)?;
    let bridge_cores = cores(&bridge, WARM_UP, window);
    let (received, delays) = watcher.finish(window);
    let _ = bridge.kill();
    let _ = bridge.wait();
    let bridge_cores = bridge_cores?;
    println!(
        "  player-ros2:           {bridge_cores:.3} cores ({:.2}x the client alone, +{:.3} cores for ROS 2)",
        bridge_cores / client_cores.max(1e-9),
        bridge_cores - client_cores
    );
    println!(
        "  ROS 2 received {:.0} scans/s ({} robots x 10 Hz = {})",
        received as f64 / window.as_secs_f64(),
        cli.robots,
        u32::from(cli.robots) * 10
    );
    let mut delays = delays;
    ensure!(
        !delays.is_empty(),
        "no scan matched between Player and ROS 2"
    );
    delays.sort_by(f64::total_cmp);
    let at = |q: f64| delays[((delays.len() - 1) as f64 * q).round() as usize] * 1e3;
    println!(
        "  Player -> ROS 2 delay over {} scans: p50 {:.2} ms, p99 {:.2} ms",
        delays.len(),
        at(0.5),
        at(0.99)
    );
    Ok(())
}

fn wait_for_robots(n: u16) -> Result<()> {
    let deadline = Instant::now() + Duration::from_secs(60);
    let last = PORT_BASE + n - 1;
    while std::net::TcpStream::connect(("127.0.0.1", last)).is_err() {
        ensure!(
            Instant::now() < deadline,
            "player-sim did not serve port {last}"
        );
        std::thread::sleep(Duration::from_millis(100));
    }
    Ok(())
}

/// Something new from any client.
#[derive(Default)]
struct News(Mutex<bool>, Condvar);

impl News {
    fn tell(&self) {
        *self.0.lock().unwrap_or_else(|e| e.into_inner()) = true;
        self.1.notify_one();
    }

    fn wait(&self, most: Duration) {
        let pending = self.0.lock().unwrap_or_else(|e| e.into_inner());
        let (mut pending, _) = self
            .1
            .wait_timeout_while(pending, most, |p| !*p)
            .unwrap_or_else(|e| e.into_inner());
        *pending = false;
    }
}

/// Player clients of the robots, subscribed to laser and position2d, told of news.
fn player_clients(n: u16, news: &Arc<News>) -> Result<Vec<Client>> {
    robots(n)
        .map(|(port, _)| {
            let news = news.clone();
            let options = ClientOptions {
                notifier: Some(Arc::new(move || news.tell())),
                ..ClientOptions::default()
            };
            let client = Client::connect("127.0.0.1", port, options)?;
            // What the bridge subscribes to: every device ROS 2 has a counterpart for (a
            // swarm robot's laser, its base, and the ranger its laser is made from).
            for device in client.devices() {
                if MAPPED.contains(&device.addr.interf) {
                    client.subscribe(device.addr)?;
                }
            }
            Ok(client)
        })
        .collect()
}

/// The baseline: the bridge's Player side — newest data of every robot taken as it comes.
fn client_only(n: u16) -> Result<()> {
    let news = Arc::new(News::default());
    let clients = player_clients(n, &news)?;
    let mut seen: HashMap<(usize, DevAddr, u8), u64> = HashMap::new();
    loop {
        news.wait(Duration::from_millis(20));
        for (i, client) in clients.iter().enumerate() {
            for stamped in client.newest_data() {
                let h = &stamped.message.header;
                let key = (i, h.addr, h.subtype);
                if seen.get(&key).is_none_or(|&s| s < stamped.seq) {
                    seen.insert(key, stamped.seq);
                    std::hint::black_box(&stamped.message.body);
                }
            }
        }
    }
}

/// A ROS 2 node reading every robot's scans, and Player clients noting when each scan came.
struct Watcher {
    stop: Arc<std::sync::atomic::AtomicBool>,
    thread: std::thread::JoinHandle<(u64, Vec<f64>)>,
    started: Instant,
}

impl Watcher {
    fn start(n: u16) -> Result<Watcher> {
        let stop = Arc::new(std::sync::atomic::AtomicBool::new(false));
        let (ready_tx, ready_rx) = std::sync::mpsc::channel();
        let thread = {
            let stop = stop.clone();
            std::thread::spawn(move || watch(n, &stop, &ready_tx))
        };
        ready_rx
            .recv_timeout(Duration::from_secs(30))
            .context("the bench's ROS 2 node")??;
        Ok(Watcher {
            stop,
            thread,
            started: Instant::now(),
        })
    }

    fn finish(self, window: Duration) -> (u64, Vec<f64>) {
        let end = self.started + WARM_UP + window;
        std::thread::sleep(end.saturating_duration_since(Instant::now()));
        self.stop.store(true, std::sync::atomic::Ordering::Relaxed);
        self.thread.join().unwrap_or_default()
    }
}

fn watch(
    n: u16,
    stop: &std::sync::atomic::AtomicBool,
    ready: &std::sync::mpsc::Sender<Result<()>>,
) -> (u64, Vec<f64>) {
    let setup = || -> Result<_> {
        let context = RosContext::new()?;
        let mut node = context.new_node(NodeName::new("/bench", "watcher")?, NodeOptions::new())?;
        let qos = QosProfile::subscription_default()
            .reliability(Reliability::BestEffort)
            .durability(Durability::Volatile)
            .history(History::KeepLast { depth: 5 });
        let mut scans = Vec::new();
        for (_, name) in robots(n) {
            let topic = node.create_topic(
                &Name::new(&format!("/{name}"), "scan")?,
                MessageTypeName::new("sensor_msgs", "LaserScan"),
                &qos,
            )?;
            scans.push(node.create_subscription::<LaserScan>(&topic, None)?);
        }
        let news = Arc::new(News::default());
        let clients = player_clients(n, &news)?;
        Ok((context, node, scans, news, clients))
    };
    let (_context, _node, scans, news, clients) = match setup() {
        Ok(parts) => {
            let _ = ready.send(Ok(()));
            parts
        }
        Err(e) => {
            let _ = ready.send(Err(e));
            return (0, Vec::new());
        }
    };
    let warm_until = Instant::now() + WARM_UP;
    // When each scan (robot, stamp) reached the bench as Player and as ROS 2.
    let mut by_player: HashMap<(usize, u64), Instant> = HashMap::new();
    let mut last_seq: Vec<u64> = vec![0; clients.len()];
    let (mut received, mut delays) = (0u64, Vec::new());
    while !stop.load(std::sync::atomic::Ordering::Relaxed) {
        // DDS samples are looked for every millisecond: the delay's resolution (this costs the
        // bench's process, not the bridge's).
        news.wait(Duration::from_millis(1));
        let now = Instant::now();
        for (i, client) in clients.iter().enumerate() {
            if let Some(stamped) =
                client.latest(client.addr(Interface::LASER, 0), Laser::DATA_SCAN.subtype())
                && stamped.seq > last_seq[i]
                && let Body::Laser(Laser::Scan(_)) = &stamped.message.body
            {
                last_seq[i] = stamped.seq;
                let stamp = Time::from_seconds(stamped.message.header.timestamp).nanos();
                by_player.insert((i, stamp), stamped.received);
            }
        }
        for (i, subscription) in scans.iter().enumerate() {
            while let Ok(Some((scan, _))) = subscription.take() {
                if now < warm_until {
                    continue;
                }
                received += 1;
                if let Some(arrived) = by_player.remove(&(i, scan.header.stamp.nanos())) {
                    delays.push(now.saturating_duration_since(arrived).as_secs_f64());
                }
            }
        }
        by_player.retain(|_, at| now.duration_since(*at) < Duration::from_secs(2));
    }
    (received, delays)
}

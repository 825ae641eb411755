//! `playerrecord record`: one client per robot, every device subscribed, every message
//! written with its receive time.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use player_proto::client::{ClientOptions, MultiClient};
use player_proto::wire::DevAddr;

/// How often progress is printed.
const PROGRESS_EVERY: Duration = Duration::from_secs(5);
/// How long the robots get for their first handshake: a robot whose server is not up yet
/// (refused, retrying) is waited for this long, since its devices are listed, and subscribed,
/// only once it has connected.
const HANDSHAKE_WAIT: Duration = Duration::from_secs(10);

/// Record robots until the time is up (or the program is stopped: a recording is readable up
/// to the last whole record whenever it ends).
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Robots: `HOST:PORT`, `HOST:FIRST-LAST` for a range of ports, or just a port.
    #[arg(required = true)]
    robots: Vec<String>,

    /// The recording to write (replaced if it exists): MCAP when it is named `*.mcap`.
    #[arg(short, long)]
    out: PathBuf,

    /// Devices to subscribe on every robot, e.g. `laser:0`; by default every device listed.
    #[arg(short, long = "device")]
    devices: Vec<String>,

    /// Stop after this many seconds; by default record until stopped.
    #[arg(short = 't', long)]
    seconds: Option<f64>,
}

/// `HOST:PORT`, `HOST:FIRST-LAST` or `PORT`, as (host, port) pairs.
fn robots(spec: &str) -> Result<Vec<(String, u16)>> {
    let (host, ports) = spec.rsplit_once(':').unwrap_or(("localhost", spec));
    let port = |p: &str| {
        p.parse::<u16>()
            .with_context(|| format!("{p:?} in {spec:?} is not a port"))
    };
    let (first, last) = match ports.split_once('-') {
        Some((a, b)) => (port(a)?, port(b)?),
        None => (port(ports)?, port(ports)?),
    };
    if first > last {
        bail!("port range {spec:?} runs backwards");
    }
    Ok((first..=last).map(|p| (host.to_string(), p)).collect())
}

pub fn run(args: Args) -> Result<()> {
    let mut wanted = Vec::new();
    for text in &args.devices {
        wanted.push(
            text.parse::<DevAddr>()
                .with_context(|| format!("device {text:?}"))?,
        );
    }
    let recorder = player_mcap::recorder(&args.out)?;
    let options = ClientOptions {
        tap: Some(recorder.tap()),
        // Every message is wanted, not only the newest.
        replace_old_data: false,
        ..ClientOptions::default()
    };
    let mut clients = MultiClient::new();
    for spec in &args.robots {
        for (host, port) in robots(spec)? {
            clients.add(&host, port, options.clone())?;
        }
    }
    let connected = clients.wait_for_connections(HANDSHAKE_WAIT);
    eprintln!("{connected} of {} robots connected", clients.len());
    // Asked of every robot at once, then waited for: 256 robots take one round trip, not 256.
    let mut pending = Vec::new();
    for client in clients.iter() {
        let devices: Vec<DevAddr> = if wanted.is_empty() {
            client.devices().iter().map(|d| d.addr).collect()
        } else {
            wanted.clone()
        };
        for addr in devices {
            let device = client.addr(addr.interf, addr.index);
            pending.push((client, device, client.subscribe_async(device)));
        }
    }
    let mut subscribed = Vec::new();
    for (client, device, reply) in pending {
        match reply.wait(options.request_timeout) {
            Ok(_) => subscribed.push((&**client, device)),
            Err(e) => {
                let (interf, index) = (device.interf, device.index);
                let (host, port) = (client.host(), client.port());
                tracing::warn!("{host}:{port} {interf}:{index} not subscribed: {e}");
            }
        }
    }
    player_proto::client::describe::describe(subscribed, options.request_timeout);
    let started = Instant::now();
    let until = args.seconds.map(|s| started + Duration::from_secs_f64(s));
    loop {
        let next = Instant::now() + PROGRESS_EVERY;
        let wake = until.map_or(next, |u| u.min(next));
        std::thread::sleep(wake.saturating_duration_since(Instant::now()));
        let stats = recorder.stats();
        eprintln!(
            "{:>6.0} s  {} records  {:.1} MB  {} lost{}",
            started.elapsed().as_secs_f64(),
            stats.written,
            stats.bytes as f64 / 1e6,
            stats.lost(),
            stats.error.map(|e| format!("  ({e})")).unwrap_or_default()
        );
        if until.is_some_and(|u| Instant::now() >= u) {
            break;
        }
    }
    drop(clients);
    let stats = recorder.finish()?;
    eprintln!(
        "wrote {} records, {} bytes, to {}; {} lost",
        stats.written,
        stats.bytes,
        args.out.display(),
        stats.lost()
    );
    if let Some(error) = stats.error {
        bail!("the recording stopped early: {error}");
    }
    Ok(())
}

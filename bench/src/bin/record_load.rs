//! Recording under load: N robots × (position2d + a B-beam laser at R Hz) from the benchmark's
//! mock server, received by one client per robot, first without recording (the baseline),
//! then with every message recorded to a file — in the same run, on the same traffic.
//!
//! Reports, per phase: messages published to the clients in the measuring window, client-side
//! CPU (robot threads, and the recorder thread), and for the recording phase the write
//! throughput, the file's growth per hour and what the recorder lost (must be 0). At the end
//! the file is read back and its DATA messages sent inside the window counted against those
//! published: the end-to-end proof that nothing was lost. The file is deleted afterwards.
//!
//! `cargo run --release -p bench --bin record_load -- --seconds 600 --file /tmp/load.prec`

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, ensure};
use bench::clock::{BenchClock, SharedWindow};
use bench::cpu::CpuSnapshot;
use bench::traffic::{DEVICES, Traffic, TrafficConfig};
use clap::Parser;
use player_proto::capture::Direction;
use player_proto::client::{Client, ClientOptions, Tap};
use player_proto::recording::{self, Event, Recorder};
use player_proto::wire::MsgType;

/// Time for every client to connect, subscribe and settle before a window opens.
const WARM_UP: Duration = Duration::from_secs(3);
/// Time after a window for what was sent inside it to arrive.
const DRAIN: Duration = Duration::from_secs(2);
const MB: f64 = 1e6;
const SECONDS_PER_HOUR: f64 = 3600.0;

#[derive(Parser, Debug)]
#[command(about = "Recording throughput and loss under a swarm's load")]
struct Cli {
    #[arg(long, default_value_t = 256)]
    robots: usize,
    #[arg(long, default_value_t = 361)]
    beams: usize,
    #[arg(long, default_value_t = 10.0)]
    rate_hz: f64,
    /// Length of the recording window.
    #[arg(long, default_value_t = 60.0)]
    seconds: f64,
    /// Length of the baseline window (same traffic, no recording).
    #[arg(long, default_value_t = 60.0)]
    baseline_seconds: f64,
    /// Where to record (deleted at the end).
    #[arg(long, default_value = "/tmp/record_load.prec")]
    file: PathBuf,
}

/// What one phase measured.
struct Phase {
    seconds: f64,
    /// The window on the bench clock: messages whose header timestamp (send time) is in it.
    window: (f64, f64),
    published: u64,
    received: u64,
    client_cpu: f64,
    recorder_cpu: f64,
}

/// Connects a client per port, subscribed to both devices, counting what is stored.
fn clients(traffic: &Traffic, tap: Option<Tap>, stored: &Arc<AtomicU64>) -> Result<Vec<Client>> {
    let mut all = Vec::new();
    for &port in traffic.ports() {
        let stored = stored.clone();
        let options = ClientOptions {
            replace_old_data: false,
            notifier: Some(Arc::new(move || {
                stored.fetch_add(1, Ordering::Relaxed);
            })),
            tap: tap.clone(),
            ..ClientOptions::default()
        };
        all.push(Client::connect("127.0.0.1", port, options).context("connecting")?);
    }
    let pending: Vec<_> = all
        .iter()
        .flat_map(|c| DEVICES.map(|i| c.subscribe_async(c.addr(i, 0))))
        .collect();
    for reply in pending {
        reply.wait(Duration::from_secs(30)).context("subscribing")?;
    }
    Ok(all)
}

/// Runs one measuring window over connected clients.
fn measure(
    traffic: &Traffic,
    clock: BenchClock,
    window: &SharedWindow,
    seconds: f64,
    stored: &AtomicU64,
    on_tick: &mut dyn FnMut(f64),
) -> Result<Phase> {
    // Called once as the window opens (t = 0), then every ten seconds.
    std::thread::sleep(WARM_UP);
    traffic.take_published();
    let cpu_before = CpuSnapshot::take("player ")?;
    let recorder_before = CpuSnapshot::take("recorder")?;
    let received_before = stored.load(Ordering::Relaxed);
    let start = clock.now();
    window.set(start, start + seconds);
    on_tick(0.0);
    let started = Instant::now();
    while started.elapsed().as_secs_f64() < seconds {
        std::thread::sleep(Duration::from_secs(10).min(Duration::from_secs_f64(
            (seconds - started.elapsed().as_secs_f64()).max(0.0),
        )));
        on_tick(started.elapsed().as_secs_f64());
    }
    let elapsed = started.elapsed().as_secs_f64();
    let received = stored.load(Ordering::Relaxed) - received_before;
    let client_cpu = CpuSnapshot::take("player ")?.since(&cpu_before);
    let recorder_cpu = CpuSnapshot::take("recorder")?.since(&recorder_before);
    std::thread::sleep(DRAIN);
    Ok(Phase {
        seconds: elapsed,
        window: (start, start + seconds),
        published: traffic.take_published(),
        received,
        client_cpu,
        recorder_cpu,
    })
}

fn main() -> Result<()> {
    let cli = Cli::parse();
    let config = TrafficConfig {
        robots: cli.robots,
        beams: cli.beams,
        rate_hz: cli.rate_hz,
    };
    let clock = BenchClock::default();
    let window = SharedWindow::default();
    let traffic = Traffic::start(config, clock, window.clone())?;
    let stored = Arc::new(AtomicU64::new(0));

    eprintln!(
        "baseline: {} robots, no recording, {} s",
        cli.robots, cli.baseline_seconds
    );
    let baseline = {
        let _clients = clients(&traffic, None, &stored)?;
        measure(
            &traffic,
            clock,
            &window,
            cli.baseline_seconds,
            &stored,
            &mut |_| {},
        )?
    };
    window.clear();

    eprintln!("recording to {} for {} s", cli.file.display(), cli.seconds);
    let recorder = Recorder::create(&cli.file)?;
    // Recorder counters at the window's start and (the last tick) its end.
    let (mut bytes_before, mut written_before) = (0, 0);
    let (mut bytes_after, mut written_after) = (0, 0);
    let recording = {
        let _clients = clients(&traffic, Some(recorder.tap()), &stored)?;
        let mut tick = |t: f64| {
            let s = recorder.stats();
            if t == 0.0 {
                (bytes_before, written_before) = (s.bytes, s.written);
            }
            (bytes_after, written_after) = (s.bytes, s.written);
            eprintln!(
                "  {t:>5.0} s  {:.0} MB  {} records  {} lost{}",
                s.bytes as f64 / MB,
                s.written,
                s.lost(),
                s.error.map(|e| format!("  ({e})")).unwrap_or_default()
            );
        };
        measure(&traffic, clock, &window, cli.seconds, &stored, &mut tick)?
    };
    let stats = recorder.finish()?;
    let window_bytes = bytes_after - bytes_before;
    let window_records = written_after - written_before;

    // End to end: every DATA message sent inside the window is in the file.
    let (start, end) = recording.window;
    let mut in_window = 0u64;
    let mut reader = recording::open(&cli.file)?;
    while let Some(record) = reader.next_record()? {
        if let Event::Message {
            direction: Direction::ServerToClient,
            header,
            ..
        } = &record.event
            && header.msg_type == MsgType::Data
            && header.timestamp >= start
            && header.timestamp < end
        {
            in_window += 1;
        }
    }
    let file_bytes = std::fs::metadata(&cli.file)?.len();
    std::fs::remove_file(&cli.file)?;

    let per_s = |n: u64, p: &Phase| n as f64 / p.seconds;
    println!("| | baseline (no recording) | recording | ratio |");
    println!("|---|---|---|---|");
    println!(
        "| window | {:.0} s | {:.0} s | |",
        baseline.seconds, recording.seconds
    );
    println!(
        "| messages published/s | {:.0} | {:.0} | {:.2} |",
        per_s(baseline.published, &baseline),
        per_s(recording.published, &recording),
        per_s(recording.published, &recording) / per_s(baseline.published, &baseline)
    );
    println!(
        "| messages received/s | {:.0} | {:.0} | {:.2} |",
        per_s(baseline.received, &baseline),
        per_s(recording.received, &recording),
        per_s(recording.received, &recording) / per_s(baseline.received, &baseline)
    );
    let cpu = |p: &Phase| (p.client_cpu + p.recorder_cpu) / p.seconds;
    println!(
        "| client CPU, s/s (robot threads + recorder) | {:.3} | {:.3} ({:.3} + {:.3}) | {:.2} |",
        cpu(&baseline),
        cpu(&recording),
        recording.client_cpu / recording.seconds,
        recording.recorder_cpu / recording.seconds,
        cpu(&recording) / cpu(&baseline)
    );
    println!(
        "| write throughput | | {:.2} MB/s, {:.0} records/s | |",
        window_bytes as f64 / MB / recording.seconds,
        window_records as f64 / recording.seconds
    );
    println!(
        "| file size per hour | | {:.1} GB | |",
        window_bytes as f64 / recording.seconds * SECONDS_PER_HOUR / 1e9
    );
    println!(
        "| recorder lost (queue full / write failed) | | {} ({} / {}) | |",
        stats.lost(),
        stats.dropped,
        stats.failed
    );
    println!(
        "| DATA sent in the window / found in the file | | {} / {} | |",
        recording.published, in_window
    );
    println!("file: {file_bytes} bytes, {} records in all", stats.written);
    ensure!(
        stats.lost() == 0,
        "the recorder lost {} records",
        stats.lost()
    );
    ensure!(
        in_window == recording.published,
        "{} messages sent in the window, {in_window} in the file",
        recording.published
    );
    Ok(())
}

//! One point of the sweep: N robots served, then each client design in turn on the same
//! server and the same generator, each measured over the same length of window.

use std::time::Duration;

use crate::BenchError;
use crate::clock::{BenchClock, SharedWindow};
use crate::cpu::CpuSnapshot;
use crate::polling::{self, Poller};
use crate::recorder::{LatencySummary, Recorder};
use crate::threaded::{self, ThreadedClients};
use crate::traffic::{Traffic, TrafficConfig};

/// The two client designs compared.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Design {
    /// Ours: one `player_proto::client::Client` thread per robot.
    ThreadPerRobot,
    /// The paper's: one thread polling every connection in turn.
    SinglePoller,
}

impl Design {
    pub fn label(self) -> &'static str {
        match self {
            Design::ThreadPerRobot => "thread per robot",
            Design::SinglePoller => "single poller",
        }
    }
}

/// How one point is measured.
#[derive(Debug, Clone, PartialEq)]
pub struct PointConfig {
    pub traffic: TrafficConfig,
    pub designs: Vec<Design>,
    /// Connected and receiving before the window opens.
    pub warmup: Duration,
    pub window: Duration,
    /// After the window closes, time for messages sent inside it to arrive.
    pub drain: Duration,
    /// The single poller's pause after a round that read nothing.
    pub idle_sleep: Duration,
}

/// What one design did at one N.
#[derive(Debug, Clone, PartialEq)]
pub struct Measurement {
    pub robots: usize,
    pub design: Design,
    pub window_s: f64,
    /// Published to this design's connections with a send time inside the window.
    pub published: u64,
    /// Of those, stored by the client as newest data.
    pub stored: u64,
    /// CPU seconds of the client-side threads per wall second of the window.
    pub client_cpu: f64,
    /// The same for the server's threads and the traffic generator (the load beside it).
    pub server_cpu: f64,
    pub client_threads: usize,
    /// Context switches of the client-side threads per wall second (wake-ups).
    pub client_switches_per_s: f64,
    pub latency: Option<LatencySummary>,
}

impl Measurement {
    pub fn handled_per_s(&self) -> f64 {
        self.stored as f64 / self.window_s
    }

    /// Published inside the window but never stored: replaced in the server's queue by a
    /// newer message of the same device (the newest-data rule both designs ask for), or
    /// still unread when the drain ended.
    pub fn lost(&self) -> u64 {
        self.published.saturating_sub(self.stored)
    }
}

/// Serves `config.traffic.robots` robots and measures each design in turn.
pub fn run_point(config: &PointConfig) -> Result<Vec<Measurement>, BenchError> {
    let clock = BenchClock::default();
    let window = SharedWindow::default();
    let traffic = Traffic::start(config.traffic, clock, window.clone())?;
    let mut results = Vec::new();
    for &design in &config.designs {
        tracing::info!(
            robots = config.traffic.robots,
            design = design.label(),
            "connecting"
        );
        let running = match design {
            Design::ThreadPerRobot => {
                Running::Threaded(ThreadedClients::start(traffic.ports(), clock, &window)?)
            }
            Design::SinglePoller => Running::Polling(Poller::start(
                traffic.ports(),
                clock,
                &window,
                config.idle_sleep,
            )?),
        };
        let start = clock.now() + config.warmup.as_secs_f64();
        let end = start + config.window.as_secs_f64();
        window.set(start, end);
        sleep_until(clock, start);
        let (client0, server0) = (running.cpu()?, server_cpu()?);
        sleep_until(clock, end);
        let (client1, server1) = (running.cpu()?, server_cpu()?);
        std::thread::sleep(config.drain);
        let recorder = running.finish(&window)?;
        window.clear();
        let published = traffic.take_published();
        let window_s = end - start;
        results.push(Measurement {
            robots: config.traffic.robots,
            design,
            window_s,
            published,
            stored: recorder.stored(),
            client_cpu: client1.since(&client0) / window_s,
            server_cpu: server1.since(&server0) / window_s,
            client_threads: client1.threads(),
            client_switches_per_s: client1.switches_since(&client0) as f64 / window_s,
            latency: LatencySummary::of(recorder.latencies()),
        });
    }
    Ok(results)
}

enum Running {
    Threaded(ThreadedClients),
    Polling(Poller),
}

impl Running {
    fn cpu(&self) -> Result<CpuSnapshot, BenchError> {
        CpuSnapshot::take(match self {
            Running::Threaded(_) => threaded::THREAD_NAME_PREFIX,
            Running::Polling(_) => polling::THREAD_NAME,
        })
    }

    fn finish(self, window: &SharedWindow) -> Result<Recorder, BenchError> {
        match self {
            Running::Threaded(clients) => Ok(clients.finish(window)),
            Running::Polling(poller) => poller.finish(),
        }
    }
}

/// The server's worker threads and the generator, together.
fn server_cpu() -> Result<CpuSnapshot, BenchError> {
    let mut both = CpuSnapshot::take("player-server")?;
    both.absorb(CpuSnapshot::take("bench-traffic")?);
    Ok(both)
}

fn sleep_until(clock: BenchClock, t: f64) {
    let now = clock.now();
    if t > now {
        std::thread::sleep(Duration::from_secs_f64(t - now));
    }
}

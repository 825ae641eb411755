//! Many observers in one process, as lightweight async tasks rather than `Client` threads: a
//! thousand robot threads on two cores would measure the scheduler, not the servers. Each
//! observer is a plain Player client — banner, a subscription per device, then reading —
//! that takes the latency of every DATA message from the send time in its header to the
//! moment it is decoded here.

use std::time::{Duration, Instant};

use bytes::BytesMut;
use player_proto::interfaces::player::{self, DeviceReq, Player};
use player_proto::message::{Body, Message};
use player_proto::transport::{Incoming, MessageReader, write_message};
use player_proto::wire::{DevAddr, FrameDecoder, MsgType, PlayerString};
use tokio::net::TcpStream;
use tokio::sync::{mpsc, watch};
use tokio::task::JoinHandle;

use crate::BenchError;
use crate::clock::{SharedWindow, unix_seconds};
use crate::traffic::DEVICES;

/// Threads the observers' runtime runs on.
const OBSERVER_THREADS: usize = 2;

/// What one observer saw inside the window.
type Seen = Result<Vec<f64>, String>;

/// A crowd of observers; stop them with [`Observers::finish`].
pub struct Observers {
    runtime: tokio::runtime::Runtime,
    stop: watch::Sender<bool>,
    tasks: Vec<JoinHandle<Seen>>,
}

/// What the crowd saw.
#[derive(Debug, Clone, Default)]
pub struct CrowdReport {
    /// Seconds from send to receipt, every DATA message sent inside the window.
    pub latencies: Vec<f64>,
    /// Observers that lost their connection or never subscribed.
    pub failed: usize,
}

impl Observers {
    /// Connects `count` observers spread evenly over `ports` and waits (at most `timeout`)
    /// until every one has its subscriptions granted.
    pub fn connect(
        ports: &[u16],
        count: usize,
        window: SharedWindow,
        timeout: Duration,
    ) -> Result<Observers, BenchError> {
        if ports.is_empty() || count == 0 {
            return Err(BenchError::Config(
                "observers need ports and a count".into(),
            ));
        }
        let runtime = tokio::runtime::Builder::new_multi_thread()
            .worker_threads(OBSERVER_THREADS)
            .thread_name("bench-observer")
            .enable_all()
            .build()
            .map_err(|e| BenchError::Thread(e.to_string()))?;
        let (stop, stopped) = watch::channel(false);
        let (ready, mut readies) = mpsc::channel(count);
        let tasks = (0..count)
            .map(|i| {
                let port = ports[i % ports.len()];
                runtime.spawn(observe(
                    port,
                    window.clone(),
                    stopped.clone(),
                    ready.clone(),
                ))
            })
            .collect();
        let deadline = Instant::now() + timeout;
        let subscribed = runtime.block_on(async {
            let mut n = 0;
            while n < count {
                let left = deadline.saturating_duration_since(Instant::now());
                match tokio::time::timeout(left, readies.recv()).await {
                    Ok(Some(())) => n += 1,
                    _ => break,
                }
            }
            n
        });
        let observers = Observers {
            runtime,
            stop,
            tasks,
        };
        if subscribed < count {
            let report = observers.finish();
            return Err(BenchError::Connect(format!(
                "{subscribed} of {count} observers subscribed within {timeout:?} ({} failed)",
                report.failed
            )));
        }
        Ok(observers)
    }

    /// Every observer goes at once, mid-stream, without unsubscribing: their sockets close
    /// with data unread, as when a viewer's process dies.
    pub fn vanish(self) {
        self.runtime.shutdown_background();
    }

    /// Stops every observer and gathers what they saw.
    pub fn finish(self) -> CrowdReport {
        let _ = self.stop.send(true);
        let mut report = CrowdReport::default();
        let outcomes = self.runtime.block_on(async {
            let mut outcomes = Vec::with_capacity(self.tasks.len());
            for task in self.tasks {
                outcomes.push(task.await);
            }
            outcomes
        });
        for outcome in outcomes {
            match outcome {
                Ok(Ok(latencies)) => report.latencies.extend(latencies),
                Ok(Err(why)) => {
                    tracing::warn!("an observer failed: {why}");
                    report.failed += 1;
                }
                Err(_) => report.failed += 1,
            }
        }
        report
    }
}

fn subscription(addr: DevAddr) -> Message {
    let req = DeviceReq {
        addr,
        access: player::OPEN_MODE,
        driver_name: PlayerString::default(),
    };
    Message::new(
        DevAddr::local(player_proto::wire::Interface::PLAYER, 0),
        MsgType::Req,
        player::REQ_DEV,
        Body::Player(Player::Device(req)),
    )
}

async fn observe(
    port: u16,
    window: SharedWindow,
    mut stop: watch::Receiver<bool>,
    ready: mpsc::Sender<()>,
) -> Seen {
    let stream = TcpStream::connect(("127.0.0.1", port))
        .await
        .map_err(|e| format!("connect to {port}: {e}"))?;
    let _ = stream.set_nodelay(true);
    let (read, mut write) = stream.into_split();
    let mut reader = MessageReader::new(read, FrameDecoder::default());
    reader.read_banner().await.map_err(|e| e.to_string())?;
    let mut scratch = BytesMut::new();
    for interf in DEVICES {
        let open = subscription(DevAddr::local(interf, 0));
        write_message(&mut write, &open, &mut scratch)
            .await
            .map_err(|e| e.to_string())?;
    }
    let mut granted = 0;
    let mut latencies = Vec::new();
    loop {
        tokio::select! {
            _ = stop.changed() => return Ok(latencies),
            incoming = reader.read() => match incoming.map_err(|e| e.to_string())? {
                Incoming::Message(m) if m.header.msg_type == MsgType::Data => {
                    let sent = m.header.timestamp;
                    if window.contains(sent) {
                        latencies.push(unix_seconds() - sent);
                    }
                }
                Incoming::Message(m) if m.header.msg_type == MsgType::Ack => {
                    granted += 1;
                    if granted == DEVICES.len() {
                        let _ = ready.send(()).await;
                    }
                }
                Incoming::Message(_) | Incoming::Undecodable(_) => {}
                Incoming::Closed => return Err(format!("port {port} closed the connection")),
            },
        }
    }
}

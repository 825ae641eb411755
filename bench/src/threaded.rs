//! Design (a), ours: one `player_proto::client::Client` per robot, each with its own thread.
//!
//! Each client's notifier runs on its robot thread right after a message was stored as newest
//! data, so reading `latest()` there returns exactly that message; its `Stamped::received`
//! is the store time and its header timestamp the send time.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, OnceLock, Weak};
use std::time::Duration;

use player_proto::client::{Client, ClientOptions, Notifier};

use crate::BenchError;
use crate::clock::{BenchClock, SharedWindow};
use crate::recorder::Recorder;
use crate::traffic::{DEVICES, PUBLISHED};

/// The first 15 bytes of a robot thread's name ("player 127.0.0.1:PORT"), as /proc shows it.
pub const THREAD_NAME_PREFIX: &str = "player 127.0.0.";

/// What one robot's notifier needs.
struct Watch {
    client: OnceLock<Weak<Client>>,
    /// Set before the client is dropped, so the notifier stops taking strong references.
    closing: AtomicBool,
    state: Mutex<WatchState>,
}

struct WatchState {
    recorder: Recorder,
    /// The newest sequence number seen per device, in [`DEVICES`] order.
    last_seq: [u64; 2],
}

/// N connected, subscribed clients.
pub struct ThreadedClients {
    robots: Vec<(Arc<Client>, Arc<Watch>)>,
}

impl ThreadedClients {
    /// Connects to every port and subscribes to both devices of each robot.
    pub fn start(
        ports: &[u16],
        clock: BenchClock,
        window: &SharedWindow,
    ) -> Result<ThreadedClients, BenchError> {
        let mut robots = Vec::with_capacity(ports.len());
        for &port in ports {
            let watch = Arc::new(Watch {
                client: OnceLock::new(),
                closing: AtomicBool::new(false),
                state: Mutex::new(WatchState {
                    recorder: Recorder::new(window.clone()),
                    last_seq: [0; 2],
                }),
            });
            let notifier: Notifier = {
                let watch = watch.clone();
                Arc::new(move || on_stored(&watch, clock))
            };
            let options = ClientOptions {
                notifier: Some(notifier),
                ..ClientOptions::default()
            };
            let client = Arc::new(
                Client::connect("127.0.0.1", port, options)
                    .map_err(|e| BenchError::Connect(e.to_string()))?,
            );
            let _ = watch.client.set(Arc::downgrade(&client));
            robots.push((client, watch));
        }
        let pending: Vec<_> = robots
            .iter()
            .flat_map(|(client, _)| {
                DEVICES.map(|interf| {
                    (
                        client.port(),
                        client.subscribe_async(client.addr(interf, 0)),
                    )
                })
            })
            .collect();
        for (port, reply) in pending {
            reply
                .wait(Duration::from_secs(10))
                .map_err(|e| BenchError::Connect(format!("subscribing on port {port}: {e}")))?;
        }
        Ok(ThreadedClients { robots })
    }

    /// Closes every connection and returns what all robot threads recorded.
    pub fn finish(self, window: &SharedWindow) -> Recorder {
        let mut all = Recorder::new(window.clone());
        for (client, watch) in self.robots {
            watch.closing.store(true, Ordering::SeqCst);
            // The notifier may hold a strong reference for a moment; the client must be
            // dropped here, never on its own thread (dropping joins that thread).
            let mut client = client;
            loop {
                match Arc::try_unwrap(client) {
                    Ok(owned) => {
                        drop(owned);
                        break;
                    }
                    Err(shared) => {
                        client = shared;
                        std::thread::yield_now();
                    }
                }
            }
            let state = std::mem::replace(
                &mut *watch.state.lock().expect("watch state"),
                WatchState {
                    recorder: Recorder::new(window.clone()),
                    last_seq: [0; 2],
                },
            );
            all.merge(state.recorder);
        }
        all
    }
}

/// Runs on a robot thread after each store: records the message that was just stored.
fn on_stored(watch: &Watch, clock: BenchClock) {
    if watch.closing.load(Ordering::SeqCst) {
        return;
    }
    let Some(client) = watch.client.get().and_then(Weak::upgrade) else {
        return;
    };
    let mut state = watch.state.lock().expect("watch state");
    for (i, kind) in PUBLISHED.iter().enumerate() {
        if let Some(stamped) = client.latest(client.addr(kind.interf, 0), kind.subtype)
            && stamped.seq != state.last_seq[i]
        {
            state.last_seq[i] = stamped.seq;
            state
                .recorder
                .record(stamped.server_time, clock.at(stamped.received));
        }
    }
}

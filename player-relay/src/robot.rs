//! One robot through the relay: its upstream client, and a thread that follows it — serving
//! the robot downstream while the upstream is connected, dropping every observer when it goes
//! (so they see the robot's server go, and come back with it), and passing each new DATA
//! message on once, to every observer's queue.

use std::collections::{HashMap, HashSet};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, SyncSender, sync_channel};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use player_proto::RobotId;
use player_proto::client::{Client, ClientOptions, ConnectionState};
use player_proto::server::Server;
use player_proto::wire::{DevAddr, Interface};

use crate::RelayError;
use crate::downstream::{DownstreamOptions, serve_robot};
use crate::subscriptions::Subscriptions;
use crate::wakes::Wakes;

/// Where a robot's downstream stands, with a signal on every change.
#[derive(Default)]
struct Serving {
    /// The downstream port, fixed once first bound so that observers find it again.
    port: Option<u16>,
    server: Option<Arc<Server>>,
}

#[derive(Default)]
struct Shared {
    serving: Mutex<Serving>,
    changed: Condvar,
}

impl Shared {
    fn lock(&self) -> MutexGuard<'_, Serving> {
        // Every change is a whole assignment: a poisoned lock still guards a consistent value.
        self.serving.lock().unwrap_or_else(|e| e.into_inner())
    }

    fn publish(&self, change: impl FnOnce(&mut Serving)) {
        change(&mut self.lock());
        self.changed.notify_all();
    }
}

/// A relayed robot; stops its thread and its servers when dropped.
pub struct RelayedRobot {
    id: RobotId,
    upstream: Arc<Client>,
    subscriptions: Arc<Subscriptions>,
    shared: Arc<Shared>,
    stop: Arc<AtomicBool>,
    wake: SyncSender<()>,
    thread: Option<JoinHandle<()>>,
}

impl RelayedRobot {
    pub(crate) fn start(
        id: &RobotId,
        listen_port: u16,
        client: ClientOptions,
        downstream: DownstreamOptions,
        survey: bool,
        subscriptions: Arc<Subscriptions>,
    ) -> Result<RelayedRobot, RelayError> {
        // One pending wake-up is enough: the thread looks at everything new when it wakes.
        let (wake, woken) = sync_channel(1);
        let notify = wake.clone();
        let wakes = Arc::new(Wakes::new(subscriptions.clone()));
        let waking = wakes.clone();
        let options = ClientOptions {
            notifier: Some(Arc::new(move || {
                if waking.wake() {
                    let _ = notify.try_send(());
                }
            })),
            ..client
        };
        let upstream = Arc::new(Client::spawn(id.host(), id.port(), options)?);
        wakes.set_client(&upstream);
        subscriptions.set_client(upstream.clone());
        let shared = Arc::new(Shared::default());
        shared.publish(|s| s.port = (listen_port != 0).then_some(listen_port));
        let stop = Arc::new(AtomicBool::new(false));
        let follower = Follower {
            id: id.clone(),
            upstream: upstream.clone(),
            shared: shared.clone(),
            stop: stop.clone(),
            downstream,
            survey,
            surveyed: false,
            subscribed: subscriptions.clone(),
            forwarded: HashMap::new(),
        };
        let thread = std::thread::Builder::new()
            .name(format!("relay {id}"))
            .spawn(move || follower.run(woken))
            .map_err(RelayError::Thread)?;
        Ok(RelayedRobot {
            id: id.clone(),
            upstream,
            subscriptions,
            shared,
            stop,
            wake,
            thread: Some(thread),
        })
    }

    /// Who the robot is, as the fronts are told.
    pub fn id(&self) -> &RobotId {
        &self.id
    }

    pub fn upstream(&self) -> &Arc<Client> {
        &self.upstream
    }

    /// The devices the relay is subscribed to upstream now: those some front looks at or
    /// some observer subscribed to (and, for a moment on each connection, all of them while
    /// the fronts' survey describes them).
    pub fn upstream_subscriptions(&self) -> Vec<player_front::Device> {
        self.subscriptions.subscribed()
    }

    /// The robot's subscriptions, as the fronts' watches see them.
    pub fn subscriptions(&self) -> &Arc<Subscriptions> {
        &self.subscriptions
    }

    /// The port observers connect to, once it is bound.
    pub fn listen_port(&self) -> Option<u16> {
        self.shared.lock().port
    }

    /// The downstream server while the robot is served.
    pub fn server(&self) -> Option<Arc<Server>> {
        self.shared.lock().server.clone()
    }

    /// Observers connected now.
    pub fn observers(&self) -> usize {
        self.server().map_or(0, |s| s.connections())
    }

    /// Waits until the robot is served downstream (`true`) or not (`false`), at most
    /// `timeout`; returns whether that came.
    pub fn wait_serving(&self, serving: bool, timeout: Duration) -> bool {
        let guard = self.shared.lock();
        let (guard, _) = self
            .shared
            .changed
            .wait_timeout_while(guard, timeout, |s| s.server.is_some() != serving)
            .unwrap_or_else(|e| e.into_inner());
        guard.server.is_some() == serving
    }
}

impl Drop for RelayedRobot {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
        let _ = self.wake.try_send(());
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// The thread's state.
struct Follower {
    id: RobotId,
    upstream: Arc<Client>,
    shared: Arc<Shared>,
    stop: Arc<AtomicBool>,
    downstream: DownstreamOptions,
    /// Whether to subscribe to everything and describe it on each connection (for fronts).
    survey: bool,
    /// Whether this connection was surveyed.
    surveyed: bool,
    subscribed: Arc<Subscriptions>,
    /// The sequence number last passed on, per device and subtype.
    forwarded: HashMap<(Interface, u16, u8), u64>,
}

/// How long to wait before trying again to serve a robot whose port could not be bound.
const REBIND_DELAY: Duration = Duration::from_secs(1);

impl Follower {
    fn run(mut self, woken: Receiver<()>) {
        let mut retry_at: Option<Instant> = None;
        loop {
            let outcome = match retry_at {
                Some(at) => woken
                    .recv_timeout(at.saturating_duration_since(Instant::now()))
                    .map_err(|e| e == std::sync::mpsc::RecvTimeoutError::Disconnected),
                None => woken.recv().map_err(|_| true),
            };
            if outcome == Err(true) || self.stop.load(Ordering::SeqCst) {
                break;
            }
            let connected = self.upstream.state() == ConnectionState::Connected;
            // The fronts' survey does not wait for the downstream port: a port that cannot be
            // bound keeps Player observers out, not the web page.
            if connected && self.survey && !self.surveyed {
                crate::survey::start(&self.id, &self.upstream, &self.subscribed);
            }
            self.surveyed = connected;
            let server = self.shared.lock().server.clone();
            match (connected, server) {
                // Data wakes the thread many times a second: a port that could not be bound
                // is tried again only once the delay is over.
                (true, None) if retry_at.is_some_and(|at| Instant::now() < at) => {}
                (true, None) => {
                    retry_at = match self.start_serving(retry_at.is_none()) {
                        true => None,
                        false => Some(Instant::now() + REBIND_DELAY),
                    };
                }
                (false, None) => retry_at = None,
                (false, Some(server)) => {
                    tracing::warn!(robot = %self.id, "robot gone: dropping its observers");
                    self.shared.publish(|s| s.server = None);
                    server.shutdown();
                }
                (true, Some(server)) => self.forward(&server),
            }
        }
        if let Some(server) = self.shared.lock().server.take() {
            server.shutdown();
        }
        self.shared.changed.notify_all();
    }

    /// Serves the robot downstream; false if its port cannot be bound now (said as an error
    /// the `first` time, then only to the debug log until it can).
    fn start_serving(&mut self, first: bool) -> bool {
        let port = self.shared.lock().port.unwrap_or(0);
        match serve_robot(&self.upstream, &self.subscribed, port, &self.downstream) {
            Ok(server) => {
                let bound = server.port(0);
                tracing::info!(robot = %self.id, port = bound, "serving the robot to observers");
                let server = Arc::new(server);
                self.shared.publish(|s| {
                    s.port = Some(bound);
                    s.server = Some(server.clone());
                });
                self.forward(&server);
                true
            }
            Err(e) if first => {
                tracing::error!(
                    robot = %self.id,
                    "cannot serve observers: {e} (trying again every {} s)",
                    REBIND_DELAY.as_secs()
                );
                false
            }
            Err(e) => {
                tracing::debug!(robot = %self.id, "still cannot serve: {e}");
                false
            }
        }
    }

    /// Passes on each DATA message not passed on yet, with the robot's own timestamp.
    fn forward(&mut self, server: &Server) {
        let port = u32::from(server.port(0));
        let publisher = server.publisher();
        let mut seen = HashSet::new();
        for stamped in self.upstream.newest_data() {
            let h = stamped.message.header;
            let key = (h.addr.interf, h.addr.index, h.subtype);
            seen.insert(key);
            if self.forwarded.get(&key) == Some(&stamped.seq) {
                continue;
            }
            self.forwarded.insert(key, stamped.seq);
            let addr = DevAddr {
                robot: port,
                ..h.addr
            };
            publisher.publish(addr, h.subtype, stamped.message.body.clone(), h.timestamp);
        }
        self.forwarded.retain(|key, _| seen.contains(key));
    }
}

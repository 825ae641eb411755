//! The receiving side: finds robots by their liveliness tokens (`player/<site>/*/alive`) and
//! serves each as an ordinary Player server on a local port, so every Player client — pv3d,
//! playerv, a script — reaches a robot on another network as if it were next door. When a
//! robot's token goes (its relay lost it, or the link to its site broke), its server stops and
//! its clients see the robot go; when the token comes back the robot is served again on the
//! same port, so clients that reconnect find it where it was. A robot costs its site only
//! what local clients look at ([`crate::feeds`]).

use std::collections::{BTreeMap, HashSet};
use std::sync::mpsc::{Receiver, RecvTimeoutError, Sender, channel};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use zenoh::Session;
use zenoh::Wait;
use zenoh::pubsub::Subscriber;
use zenoh::sample::SampleKind;

use crate::bridge_config::FromZenohConfig;
use crate::error::ZenohError;
use crate::keys::{RobotKey, alive_of_site};
use crate::remote::{Remote, serve};

/// How often a robot whose devices could not be had yet is tried again.
const RETRY: Duration = Duration::from_millis(500);

enum Event {
    Appeared(RobotKey),
    Gone(RobotKey),
    /// The bridge is dropped (the liveliness callback's sender outlives the thread).
    Stop,
}

#[derive(Default)]
struct State {
    /// Every robot ever served, and its port: kept when it goes, for when it comes back.
    ports: BTreeMap<RobotKey, u16>,
    serving: BTreeMap<RobotKey, Remote>,
}

#[derive(Default)]
struct Shared {
    state: Mutex<State>,
    changed: Condvar,
}

impl Shared {
    fn lock(&self) -> MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// A running bridge; stops every local server when dropped.
pub struct FromZenoh {
    shared: Arc<Shared>,
    events: Option<Sender<Event>>,
    thread: Option<JoinHandle<()>>,
    _liveliness: Subscriber<()>,
}

impl FromZenoh {
    pub fn start(session: Session, config: FromZenohConfig) -> Result<FromZenoh, ZenohError> {
        let (events, received) = channel();
        let shared = Arc::new(Shared::default());
        let key = alive_of_site(&config.site);
        let tell = events.clone();
        let liveliness = session
            .liveliness()
            .declare_subscriber(&key)
            .history(true)
            .callback(move |sample| {
                let Some(robot) = RobotKey::of_key(sample.key_expr().as_str()) else {
                    return;
                };
                let _ = tell.send(match sample.kind() {
                    SampleKind::Put => Event::Appeared(robot),
                    SampleKind::Delete => Event::Gone(robot),
                });
            })
            .wait()?;
        // Those already there (the subscriber's history says so too; twice is harmless).
        for reply in session.liveliness().get(&key).wait()?.try_iter() {
            if let Some(robot) = reply
                .result()
                .ok()
                .and_then(|s| RobotKey::of_key(s.key_expr().as_str()))
            {
                let _ = events.send(Event::Appeared(robot));
            }
        }
        let follower = Follower {
            session,
            config,
            shared: shared.clone(),
            waiting: HashSet::new(),
        };
        let thread = std::thread::Builder::new()
            .name("from-zenoh".into())
            .spawn(move || follower.run(received))?;
        Ok(FromZenoh {
            shared,
            events: Some(events),
            thread: Some(thread),
            _liveliness: liveliness,
        })
    }

    /// The robots served now, with their local ports.
    pub fn serving(&self) -> Vec<(RobotKey, u16)> {
        let state = self.shared.lock();
        state
            .serving
            .iter()
            .map(|(robot, remote)| (robot.clone(), remote.server.port(0)))
            .collect()
    }

    /// Devices whose data is subscribed to in Zenoh now (a local client looks at each), over
    /// every robot served.
    pub fn data_subscriptions(&self) -> usize {
        let state = self.shared.lock();
        state
            .serving
            .values()
            .map(|remote| remote.feeds.subscriptions())
            .sum()
    }

    /// Waits until `n` robots at least are served, at most `timeout`; returns them.
    pub fn wait_for_robots(&self, n: usize, timeout: Duration) -> Vec<(RobotKey, u16)> {
        let guard = self.shared.lock();
        let _ = self
            .shared
            .changed
            .wait_timeout_while(guard, timeout, |s| s.serving.len() < n)
            .unwrap_or_else(|e| e.into_inner());
        self.serving()
    }

    /// Waits until `robot` is served (`Some(port)`) or not (`None`), at most `timeout`.
    pub fn wait_serving(&self, robot: &RobotKey, serving: bool, timeout: Duration) -> Option<u16> {
        let guard = self.shared.lock();
        let (guard, _) = self
            .shared
            .changed
            .wait_timeout_while(guard, timeout, |s| s.serving.contains_key(robot) != serving)
            .unwrap_or_else(|e| e.into_inner());
        guard.serving.get(robot).map(|r| r.server.port(0))
    }
}

impl Drop for FromZenoh {
    fn drop(&mut self) {
        if let Some(events) = self.events.take() {
            let _ = events.send(Event::Stop);
        }
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// The thread that starts and stops the local servers.
struct Follower {
    session: Session,
    config: FromZenohConfig,
    shared: Arc<Shared>,
    /// Robots alive whose devices could not be had yet.
    waiting: HashSet<RobotKey>,
}

impl Follower {
    fn run(mut self, events: Receiver<Event>) {
        loop {
            let timeout = if self.waiting.is_empty() {
                Duration::from_secs(1)
            } else {
                RETRY
            };
            match events.recv_timeout(timeout) {
                Ok(Event::Appeared(robot)) => self.appeared(robot),
                Ok(Event::Gone(robot)) => self.gone(&robot),
                Err(RecvTimeoutError::Timeout) => {
                    for robot in std::mem::take(&mut self.waiting) {
                        self.appeared(robot);
                    }
                }
                Ok(Event::Stop) | Err(RecvTimeoutError::Disconnected) => break,
            }
        }
        let serving = std::mem::take(&mut self.shared.lock().serving);
        drop(serving);
        self.shared.changed.notify_all();
    }

    fn appeared(&mut self, robot: RobotKey) {
        if self.shared.lock().serving.contains_key(&robot) {
            return;
        }
        let port = {
            let state = self.shared.lock();
            match state.ports.get(&robot) {
                Some(&port) => port,
                None if self.config.base_port == 0 => 0,
                None => {
                    let n = u16::try_from(state.ports.len()).unwrap_or(u16::MAX);
                    self.config.base_port.saturating_add(n)
                }
            }
        };
        let started = Instant::now();
        match serve(&self.session, &robot, port, &self.config) {
            Ok(remote) => {
                let port = remote.server.port(0);
                tracing::info!(%robot, port, took = ?started.elapsed(), "serving a robot found in Zenoh");
                let mut state = self.shared.lock();
                state.ports.insert(robot.clone(), port);
                state.serving.insert(robot, remote);
                drop(state);
                self.shared.changed.notify_all();
            }
            Err(e) => {
                tracing::warn!(%robot, "not served yet: {e}");
                self.waiting.insert(robot);
            }
        }
    }

    fn gone(&mut self, robot: &RobotKey) {
        self.waiting.remove(robot);
        let remote = self.shared.lock().serving.remove(robot);
        if let Some(remote) = remote {
            tracing::info!(%robot, port = remote.server.port(0), "robot gone from Zenoh: no longer served");
            drop(remote);
            self.shared.changed.notify_all();
        }
    }
}

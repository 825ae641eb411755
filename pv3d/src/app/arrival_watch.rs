//! Waking the window when a Player server answers. A server that answers only after the viewer
//! started (or comes back after a stall) has no plugins yet, so none of its data is asked for,
//! and the data notifier that wakes the window never runs: its plugins would appear only at the
//! next mouse move. This watch turns "a server finished its handshake" into the same wake-up.
//!
//! The client offers no signal for a change of connection state yet, so the watch looks at
//! every server's state a few times a second, on a thread of its own; it wakes the window only
//! when a server has become connected since the last look.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;
use std::time::Duration;

use player_proto::client::{ConnectionState, Notifier};

use crate::robots::RobotManager;

/// How often the servers' states are looked at: well under the second a server takes to be
/// reconnected, so its plugins come with it.
const LOOK_EVERY: Duration = Duration::from_millis(100);

/// The running watch; dropping it stops the thread.
pub struct ArrivalWatch {
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl ArrivalWatch {
    /// Calls `wake` whenever one of `robots`' servers becomes connected. A server connected
    /// already counts as arriving at the first look: the viewer may have been composed just
    /// before it answered, and one wake-up too many costs a frame, one too few its plugins.
    pub fn start(robots: Arc<RobotManager>, wake: Notifier) -> ArrivalWatch {
        let stop = Arc::new(AtomicBool::new(false));
        let stopped = stop.clone();
        let thread = std::thread::Builder::new()
            .name("pv3d-server-arrivals".into())
            .spawn(move || {
                let mut was_connected: Vec<bool> = Vec::new();
                while !stopped.load(Ordering::Acquire) {
                    let connected = connected_now(&robots);
                    let arrived = connected
                        .iter()
                        .enumerate()
                        .any(|(i, now)| *now && !was_connected.get(i).copied().unwrap_or(false));
                    if arrived {
                        wake();
                    }
                    was_connected = connected;
                    std::thread::park_timeout(LOOK_EVERY);
                }
            });
        let thread = match thread {
            Ok(thread) => Some(thread),
            Err(e) => {
                tracing::error!("no thread to watch for servers answering late: {e}");
                None
            }
        };
        ArrivalWatch { stop, thread }
    }
}

/// Whether each server (in the manager's order) is connected.
fn connected_now(robots: &RobotManager) -> Vec<bool> {
    robots
        .clients()
        .map(|(_, _, client)| client.state() == ConnectionState::Connected)
        .collect()
}

impl Drop for ArrivalWatch {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Release);
        if let Some(thread) = self.thread.take() {
            thread.thread().unpark();
            let _ = thread.join();
        }
    }
}

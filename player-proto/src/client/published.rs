//! What the robot thread tells the handle about the connection: a snapshot only the thread
//! writes, and a signal on every change so that a caller waits for a state rather than
//! polling for it.

use std::fmt;
use std::sync::{Condvar, Mutex, MutexGuard};
use std::time::Instant;

use crate::delivery::{DataMode, ReplaceRule};
use crate::wire::{Banner, DevAddr};

/// Where a connection stands.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ConnectionState {
    Connecting,
    Connected,
    /// The server went away; retrying (this is the `attempt`-th try since).
    Reconnecting {
        attempt: u32,
    },
    /// Gave up, or was refused for good (not a Player 3 server).
    Failed(String),
}

impl fmt::Display for ConnectionState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ConnectionState::Connecting => f.write_str("connecting"),
            ConnectionState::Connected => f.write_str("connected"),
            ConnectionState::Reconnecting { attempt } => {
                write!(f, "reconnecting (attempt {attempt})")
            }
            ConnectionState::Failed(why) => write!(f, "failed: {why}"),
        }
    }
}

/// A device the server reported, with its driver's name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DeviceInfo {
    pub addr: DevAddr,
    pub driver: String,
}

/// The connection as the robot thread last described it.
#[derive(Debug, Clone)]
pub(crate) struct Snapshot {
    pub state: ConnectionState,
    pub banner: Option<Banner>,
    /// From the last handshake.
    pub devices: Vec<DeviceInfo>,
    /// Why the last connection ended (lost, stalled, refused), for a status line.
    pub last_disconnect: Option<String>,
    /// The data mode in force, or to be restored on the next connection.
    pub data_mode: DataMode,
    /// The replace rules in force, in the order the server tries them.
    pub replace_rules: Vec<ReplaceRule>,
    /// Messages the server sent that could not be used (undecodable, a reply to nothing).
    pub rejected: u64,
}

impl Snapshot {
    pub fn new(data_mode: DataMode) -> Snapshot {
        Snapshot {
            state: ConnectionState::Connecting,
            banner: None,
            devices: Vec::new(),
            last_disconnect: None,
            data_mode,
            replace_rules: Vec::new(),
            rejected: 0,
        }
    }
}

/// The snapshot and its change signal.
pub(crate) struct Board {
    snapshot: Mutex<Snapshot>,
    changed: Condvar,
}

impl Board {
    pub fn new(snapshot: Snapshot) -> Board {
        Board {
            snapshot: Mutex::new(snapshot),
            changed: Condvar::new(),
        }
    }

    fn lock(&self) -> MutexGuard<'_, Snapshot> {
        // A reader that panicked cannot have left a snapshot half-written: every change is a
        // plain field assignment. So a poisoned lock is still safe to use.
        self.snapshot.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Changes the snapshot (robot thread only) and wakes everyone waiting on it.
    pub fn publish(&self, change: impl FnOnce(&mut Snapshot)) {
        change(&mut self.lock());
        self.changed.notify_all();
    }

    pub fn read<T>(&self, look: impl FnOnce(&Snapshot) -> T) -> T {
        look(&self.lock())
    }

    /// Blocks until `found` finds something in the snapshot or `deadline` passes; returns
    /// what it found.
    pub fn wait_until<T>(
        &self,
        deadline: Instant,
        mut found: impl FnMut(&Snapshot) -> Option<T>,
    ) -> Option<T> {
        let timeout = deadline.saturating_duration_since(Instant::now());
        let (snapshot, _) = self
            .changed
            .wait_timeout_while(self.lock(), timeout, |s| found(s).is_none())
            .unwrap_or_else(|e| e.into_inner());
        found(&snapshot)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;
    use std::time::Duration;

    #[test]
    fn a_waiter_wakes_on_the_change_it_waits_for() {
        let board = Arc::new(Board::new(Snapshot::new(DataMode::Push)));
        let writer = board.clone();
        let thread = std::thread::spawn(move || {
            writer.publish(|s| s.rejected = 1);
            writer.publish(|s| s.state = ConnectionState::Connected);
        });
        let deadline = Instant::now() + Duration::from_secs(60);
        let connected =
            |s: &Snapshot| (s.state == ConnectionState::Connected).then_some(s.rejected);
        assert_eq!(board.wait_until(deadline, connected), Some(1));
        thread.join().unwrap();
    }

    #[test]
    fn a_passed_deadline_answers_at_once() {
        let board = Board::new(Snapshot::new(DataMode::Push));
        let state = |s: &Snapshot| Some(s.state.clone());
        let connected = |s: &Snapshot| (s.state == ConnectionState::Connected).then_some(());
        assert_eq!(board.wait_until(Instant::now(), connected), None);
        assert_eq!(
            board.wait_until(Instant::now(), state),
            Some(ConnectionState::Connecting)
        );
    }
}

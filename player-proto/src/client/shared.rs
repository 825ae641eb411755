//! State the robot thread writes and the user-facing handle reads: connection state, device
//! list, and the newest data of each subscribed device.

use std::collections::{HashMap, HashSet};
use std::fmt;
use std::sync::{Arc, Mutex};
use std::time::Instant;

use super::options::DataMode;
use super::replace_rule::ReplaceRule;
use crate::message::Message;
use crate::wire::{Banner, DevAddr, Interface};

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

/// A data message as stored: when it arrived, the server's timestamp, and a sequence number
/// counting this device's messages of this subtype (a viewer redraws when it changes).
#[derive(Debug, Clone)]
pub struct Stamped {
    pub message: Arc<Message>,
    pub received: Instant,
    pub server_time: f64,
    pub seq: u64,
}

/// Key of the newest-data store.
pub(crate) type DataKey = (Interface, u16, u8);

/// Per-device counters for rates.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct DeviceStats {
    /// DATA messages.
    pub messages: u64,
    pub bytes: u64,
    /// Readings: DATA messages with a server time of their own. A driver that sends one
    /// reading as several messages stamped alike (Stage's ranger: ranges, then intensities)
    /// counts once, so this is the rate a person means by "10 Hz".
    pub updates: u64,
    /// The server time of the last DATA message, s (what tells a new reading).
    pub(crate) last_server_time: f64,
}

#[derive(Default)]
pub(crate) struct Shared {
    pub state: Mutex<Option<ConnectionState>>,
    pub banner: Mutex<Option<Banner>>,
    pub devices: Mutex<Vec<DeviceInfo>>,
    /// What the user subscribed to, restored after a reconnect.
    pub subscriptions: Mutex<HashSet<(Interface, u16)>>,
    /// The data mode asked for last, restored after a reconnect.
    pub data_mode: Mutex<DataMode>,
    /// The replace rules asked for, in the order the server applies them; restored after a
    /// reconnect in that order.
    pub replace_rules: Mutex<Vec<ReplaceRule>>,
    /// Why the last connection ended (lost, stalled, refused), for a status line.
    pub last_disconnect: Mutex<Option<String>>,
    /// Newest DATA per (interface, index, subtype), subscribed devices only: bounded by the
    /// subscriptions, whatever the server sends.
    pub latest: Mutex<HashMap<DataKey, Stamped>>,
    pub stats: Mutex<HashMap<(Interface, u16), DeviceStats>>,
    /// Messages the server sent that could not be used (undecodable, a reply to nothing).
    pub rejected: Mutex<u64>,
}

impl Shared {
    /// Fresh state seeded with the connect-time data mode and replace rule.
    pub fn new(data_mode: DataMode, replace_old_data: bool) -> Shared {
        let shared = Shared::default();
        *shared.data_mode.lock().expect("data mode") = data_mode;
        if replace_old_data {
            shared
                .replace_rules
                .lock()
                .expect("replace rules")
                .push(ReplaceRule::newest_data());
        }
        shared
    }

    pub fn set_state(&self, state: ConnectionState) {
        *self.state.lock().expect("state") = Some(state);
    }

    pub fn state(&self) -> ConnectionState {
        self.state
            .lock()
            .expect("state")
            .clone()
            .unwrap_or(ConnectionState::Connecting)
    }

    pub fn is_subscribed(&self, interf: Interface, index: u16) -> bool {
        self.subscriptions
            .lock()
            .expect("subscriptions")
            .contains(&(interf, index))
    }

    /// Stores a DATA message of a subscribed device; returns whether it was kept.
    pub fn store(&self, message: Message, size: usize) -> bool {
        let a = message.header.addr;
        if !self.is_subscribed(a.interf, a.index) {
            return false;
        }
        {
            let mut stats = self.stats.lock().expect("stats");
            let s = stats.entry((a.interf, a.index)).or_default();
            s.messages += 1;
            s.bytes += size as u64;
            if s.updates == 0 || message.header.timestamp != s.last_server_time {
                s.updates += 1;
                s.last_server_time = message.header.timestamp;
            }
        }
        let key = (a.interf, a.index, message.header.subtype);
        let mut latest = self.latest.lock().expect("latest");
        let seq = latest.get(&key).map_or(1, |s| s.seq + 1);
        latest.insert(
            key,
            Stamped {
                server_time: message.header.timestamp,
                message: Arc::new(message),
                received: Instant::now(),
                seq,
            },
        );
        true
    }

    pub fn forget(&self, interf: Interface, index: u16) {
        self.latest
            .lock()
            .expect("latest")
            .retain(|(i, n, _), _| !(*i == interf && *n == index));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interfaces::ranger::{Ranger, RangerIntensities, RangerRanges};
    use crate::wire::{DevAddr, MsgType};

    fn stamped(body: Ranger, time: f64) -> Message {
        let addr: DevAddr = "ranger:0".parse().unwrap();
        let mut m = Message::typed(addr, MsgType::Data, body);
        m.header.timestamp = time;
        m
    }

    #[test]
    fn a_reading_sent_as_several_messages_counts_as_one_update() {
        let shared = Shared::new(DataMode::Push, false);
        shared
            .subscriptions
            .lock()
            .unwrap()
            .insert((Interface::RANGER, 0));
        for time in [1.0, 1.1] {
            let ranges = RangerRanges { ranges: vec![1.0] };
            let intensities = RangerIntensities {
                intensities: vec![1.0],
            };
            assert!(shared.store(stamped(Ranger::Ranges(ranges), time), 60));
            assert!(shared.store(stamped(Ranger::Intensities(intensities), time), 60));
        }
        let stats = shared.stats.lock().unwrap()[&(Interface::RANGER, 0)];
        assert_eq!((stats.messages, stats.updates), (4, 2));
    }
}

//! The newest data of each subscribed device, with counters for rates. The robot thread
//! writes it (only for devices it holds subscribed, so it stays bounded whatever the server
//! sends); the handle reads it without waiting for anything but the lock.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Instant;

use crate::message::Message;
use crate::wire::Interface;

/// A data message as stored: when it arrived, the server's timestamp, and a sequence number
/// counting this device's messages of this subtype (a viewer redraws when it changes).
#[derive(Debug, Clone)]
pub struct Stamped {
    pub message: Arc<Message>,
    pub received: Instant,
    pub server_time: f64,
    pub seq: u64,
}

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

impl DeviceStats {
    /// Counts one DATA message of `size` bytes, stamped `server_time` by its server. Whatever
    /// else shows a device's rate (the web page's rows) counts with this too, so that a
    /// sensor reads "10 Hz" in every view.
    pub fn count(&mut self, server_time: f64, size: usize) {
        self.messages += 1;
        self.bytes += size as u64;
        if self.updates == 0 || server_time != self.last_server_time {
            self.updates += 1;
            self.last_server_time = server_time;
        }
    }
}

/// A device as the store keys it.
type DeviceKey = (Interface, u16);
/// Newest data is kept per device and subtype.
type DataKey = (Interface, u16, u8);

#[derive(Default)]
pub(crate) struct DataStore {
    latest: Mutex<HashMap<DataKey, Stamped>>,
    stats: Mutex<HashMap<DeviceKey, DeviceStats>>,
}

/// Every change is a whole insert or removal, so a lock poisoned by a panicking reader still
/// guards consistent data.
fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(|e| e.into_inner())
}

impl DataStore {
    /// Stores a DATA message (the caller has checked that its device is subscribed).
    pub fn store(&self, message: Message, size: usize) {
        let a = message.header.addr;
        {
            let mut stats = lock(&self.stats);
            let s = stats.entry((a.interf, a.index)).or_default();
            s.count(message.header.timestamp, size);
        }
        let key = (a.interf, a.index, message.header.subtype);
        let mut latest = lock(&self.latest);
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
    }

    /// Drops a device's data (it was unsubscribed).
    pub fn forget(&self, interf: Interface, index: u16) {
        lock(&self.latest).retain(|(i, n, _), _| !(*i == interf && *n == index));
    }

    pub fn latest(&self, interf: Interface, index: u16, subtype: u8) -> Option<Stamped> {
        lock(&self.latest).get(&(interf, index, subtype)).cloned()
    }

    /// The newest message of every subscribed device and subtype.
    pub fn all_latest(&self) -> Vec<Stamped> {
        lock(&self.latest).values().cloned().collect()
    }

    pub fn stats(&self, interf: Interface, index: u16) -> DeviceStats {
        lock(&self.stats)
            .get(&(interf, index))
            .copied()
            .unwrap_or_default()
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
        let store = DataStore::default();
        for time in [1.0, 1.1] {
            let ranges = RangerRanges { ranges: vec![1.0] };
            let intensities = RangerIntensities {
                intensities: vec![1.0],
            };
            store.store(stamped(Ranger::Ranges(ranges), time), 60);
            store.store(stamped(Ranger::Intensities(intensities), time), 60);
        }
        let stats = store.stats(Interface::RANGER, 0);
        assert_eq!((stats.messages, stats.updates), (4, 2));
        assert_eq!(store.latest(Interface::RANGER, 0, 1).unwrap().seq, 2);
        store.forget(Interface::RANGER, 0);
        assert!(store.latest(Interface::RANGER, 0, 1).is_none());
    }
}

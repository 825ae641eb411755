//! What each Player server has listed, compared handshake by handshake: a server restarted
//! with fewer devices, or more, or the same ones again, tells the composer which devices are
//! new (their handlers' plugins are made), which went away (their plugins are cleaned) and
//! which came back (their plugins resume).

use std::collections::{BTreeSet, HashMap};

use player_proto::Interface;

use super::FoundDevice;

/// A device as its server knows it: interface and index. Host and robot numbers in a
/// reported address may differ between two runs of the same server, so they are left out.
type DeviceKey = (Interface, u16);

fn key_of(device: &FoundDevice) -> DeviceKey {
    (device.addr.interf, device.addr.index)
}

/// How one server's list changed since it was last seen.
#[derive(Debug, Default, PartialEq)]
pub struct ListChange {
    /// Listed for the first time: the handlers have not seen them yet.
    pub new: Vec<FoundDevice>,
    /// Listed last time, not any more.
    pub gone: Vec<FoundDevice>,
    /// Listed again after they had gone.
    pub back: Vec<FoundDevice>,
}

#[derive(Default)]
struct ServerRecord {
    /// The list of the server's last handshake, as last seen.
    listed: Vec<FoundDevice>,
    /// Every device it has ever listed.
    ever: BTreeSet<DeviceKey>,
}

/// The device lists of every server seen so far, by host and port.
#[derive(Default)]
pub struct DeviceLedger {
    servers: HashMap<(String, u16), ServerRecord>,
}

impl DeviceLedger {
    /// Takes in the list `server` reports now and says how it changed. Listing the same
    /// devices again (the usual case, every frame) changes nothing.
    pub fn observe(&mut self, server: (String, u16), listed: Vec<FoundDevice>) -> ListChange {
        let record = self.servers.entry(server).or_default();
        let unchanged = record.listed.len() == listed.len()
            && record
                .listed
                .iter()
                .zip(&listed)
                .all(|(a, b)| key_of(a) == key_of(b));
        if unchanged {
            return ListChange::default();
        }
        let now: BTreeSet<DeviceKey> = listed.iter().map(key_of).collect();
        let before: BTreeSet<DeviceKey> = record.listed.iter().map(key_of).collect();
        let mut change = ListChange::default();
        for device in &listed {
            let key = key_of(device);
            if !record.ever.contains(&key) {
                change.new.push(device.clone());
            } else if !before.contains(&key) {
                change.back.push(device.clone());
            }
        }
        change.gone = record
            .listed
            .iter()
            .filter(|d| !now.contains(&key_of(d)))
            .cloned()
            .collect();
        record.ever.extend(now);
        record.listed = listed;
        change
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn device(text: &str) -> FoundDevice {
        FoundDevice {
            host: "127.0.0.1".into(),
            port: 6665,
            addr: text.parse().unwrap(),
            driver: "sim".into(),
        }
    }

    fn server() -> (String, u16) {
        ("127.0.0.1".into(), 6665)
    }

    fn names(devices: &[FoundDevice]) -> Vec<String> {
        devices
            .iter()
            .map(|d| format!("{}:{}", d.addr.interf, d.addr.index))
            .collect()
    }

    #[test]
    fn a_restarted_server_with_a_device_less_then_more_is_told_apart() {
        let mut ledger = DeviceLedger::default();
        let first = ledger.observe(server(), vec![device("position2d:0"), device("laser:0")]);
        assert_eq!(names(&first.new), ["position2d:0", "laser:0"]);
        assert!(first.gone.is_empty() && first.back.is_empty());
        assert_eq!(
            ledger.observe(server(), vec![device("position2d:0"), device("laser:0")]),
            ListChange::default(),
            "the same list again changes nothing"
        );

        let fewer = ledger.observe(server(), vec![device("position2d:0")]);
        assert_eq!(names(&fewer.gone), ["laser:0"]);
        assert!(fewer.new.is_empty() && fewer.back.is_empty());

        let more = ledger.observe(
            server(),
            vec![device("position2d:0"), device("laser:0"), device("sonar:0")],
        );
        assert_eq!(names(&more.back), ["laser:0"]);
        assert_eq!(names(&more.new), ["sonar:0"]);
        assert!(more.gone.is_empty());
    }

    #[test]
    fn a_server_that_lists_nothing_at_first_still_gets_its_devices_later() {
        let mut ledger = DeviceLedger::default();
        assert_eq!(ledger.observe(server(), Vec::new()), ListChange::default());
        let later = ledger.observe(server(), vec![device("laser:0")]);
        assert_eq!(names(&later.new), ["laser:0"]);
    }
}

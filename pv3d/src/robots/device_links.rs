//! The device links plugins share, counted by the plugins that hold them: the table holds
//! each link weakly, so a link lives exactly as long as some plugin holds it, and the last
//! plugin that lets a device go ends its subscription (see [`ClientDevice`]'s drop).

use std::collections::HashMap;
use std::sync::{Arc, Mutex, MutexGuard, Weak};

use player_proto::client::Client;
use player_proto::wire::DevAddr;

use super::device_link::ClientDevice;

/// A device on a server: host, port, address.
pub type LinkKey = (String, u16, DevAddr);

/// The links plugins hold now, by device. Cheap to clone: every clone is the same table.
#[derive(Clone, Default)]
pub struct DeviceLinks(Arc<Mutex<HashMap<LinkKey, Weak<ClientDevice>>>>);

impl DeviceLinks {
    /// The link to `key`'s device: the one plugins already hold, or a new one that subscribes.
    pub fn link(&self, client: &Arc<Client>, key: LinkKey) -> Arc<ClientDevice> {
        let mut table = self.lock();
        if let Some(held) = table.get(&key).and_then(Weak::upgrade) {
            return held;
        }
        let link = Arc::new(ClientDevice::new(client.clone(), key.clone(), self.clone()));
        table.insert(key, Arc::downgrade(&link));
        link
    }

    /// The devices some plugin holds now, sorted.
    pub fn held(&self) -> Vec<LinkKey> {
        let mut held: Vec<LinkKey> = self
            .lock()
            .iter()
            .filter(|(_, link)| link.strong_count() > 0)
            .map(|(key, _)| key.clone())
            .collect();
        held.sort();
        held
    }

    /// The last plugin let `key`'s link go. Returns whether its subscription is to end:
    /// not when a plugin asked for the device again meanwhile, since the link made for that
    /// one subscribed anew and the subscription is its now.
    pub(super) fn released(&self, key: &LinkKey) -> LinkRelease<'_> {
        let mut table = self.lock();
        let superseded = table.get(key).is_some_and(|link| link.strong_count() > 0);
        if !superseded {
            table.remove(key);
        }
        LinkRelease {
            end_subscription: !superseded,
            _table: table,
        }
    }

    fn lock(&self) -> MutexGuard<'_, HashMap<LinkKey, Weak<ClientDevice>>> {
        // Every change is a single insert or remove: a panic elsewhere cannot leave the table
        // half-changed, so a poisoned lock is still safe to use.
        self.0.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// A released link's verdict, with the table held: the unsubscription goes out before any
/// new link to the same device can subscribe, so the server sees the close before the open.
pub(super) struct LinkRelease<'a> {
    pub end_subscription: bool,
    _table: MutexGuard<'a, HashMap<LinkKey, Weak<ClientDevice>>>,
}

//! A plugin's view of its device, over the shared client of the device's server, and the
//! table of those links, counted by the plugins that hold them. Plugins of the same device
//! share one link: it subscribes when made and unsubscribes when the last of them lets it go.
//! The table holds each link weakly, so a link lives exactly as long as some plugin holds it,
//! and the last plugin that lets a device go ends its subscription (see [`ClientDevice`]'s
//! drop). A link tells its table when it goes, and the table makes the links: one module, as
//! neither is whole without the other.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, MutexGuard, Weak};

use framework::device::DeviceAccess;
use player_proto::client::{Client, ConnectionState, PendingReply, Stamped};
use player_proto::interfaces::kind::MessageKind;
use player_proto::message::Body;
use player_proto::wire::DevAddr;

/// A device on a server: host, port, address.
pub type LinkKey = (String, u16, DevAddr);

/// One device on a shared client. Subscribes on creation, without waiting. A kind is read
/// and requested by its subtype on this device's own address.
pub struct ClientDevice {
    client: Arc<Client>,
    key: LinkKey,
    /// The table this link is in, told when the link goes.
    links: DeviceLinks,
    subscription: Mutex<Option<PendingReply>>,
}

impl ClientDevice {
    fn new(client: Arc<Client>, key: LinkKey, links: DeviceLinks) -> ClientDevice {
        let pending = client.subscribe_async(key.2);
        ClientDevice {
            client,
            key,
            links,
            subscription: Mutex::new(Some(pending)),
        }
    }

    fn addr(&self) -> DevAddr {
        self.key.2
    }

    fn check_subscription(&self) {
        let mut slot = self.subscription.lock().expect("subscription");
        let Some(pending) = slot.as_ref() else { return };
        if let Some(outcome) = pending.try_get() {
            if let Err(e) = outcome {
                tracing::warn!(device = %self.addr(), port = self.client.port(), "subscription failed: {e}");
            }
            *slot = None;
        }
    }
}

impl DeviceAccess for ClientDevice {
    fn latest(&self, kind: MessageKind) -> Option<Stamped> {
        self.check_subscription();
        self.client.latest(self.addr(), kind.subtype)
    }

    fn command(&self, body: Body) {
        self.client.command(self.addr(), body);
    }

    fn request(&self, kind: MessageKind, body: Body) -> PendingReply {
        self.client.request_async(self.addr(), kind.subtype, body)
    }

    fn link_state(&self) -> ConnectionState {
        self.client.state()
    }

    fn read_only(&self) -> bool {
        self.client.is_read_only()
    }
}

impl Drop for ClientDevice {
    /// The last plugin using the device let it go: end the subscription, so that the server
    /// stops sending what nobody draws and a reconnect does not restore it. Without waiting
    /// for the reply: this runs on the UI thread.
    fn drop(&mut self) {
        let release = self.links.released(&self.key);
        if release.end_subscription {
            tracing::debug!(device = %self.addr(), port = self.client.port(), "no plugin uses it any more: unsubscribing");
            // The reply only confirms; nobody waits for it.
            drop(self.client.unsubscribe_async(self.addr()));
        }
    }
}

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
    fn released(&self, key: &LinkKey) -> LinkRelease<'_> {
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
struct LinkRelease<'a> {
    pub end_subscription: bool,
    _table: MutexGuard<'a, HashMap<LinkKey, Weak<ClientDevice>>>,
}

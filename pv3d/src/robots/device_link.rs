//! A plugin's view of its device, over the shared client of the device's server. Plugins of
//! the same device share one link (see [`super::DeviceLinks`]); it subscribes when made and
//! unsubscribes when the last of them lets it go.

use std::sync::{Arc, Mutex};

use framework::device::DeviceAccess;
use player_proto::client::{Client, ConnectionState, PendingReply, Stamped};
use player_proto::interfaces::kind::MessageKind;
use player_proto::message::Body;
use player_proto::wire::DevAddr;

use super::device_links::{DeviceLinks, LinkKey};

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
    pub(super) fn new(client: Arc<Client>, key: LinkKey, links: DeviceLinks) -> ClientDevice {
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

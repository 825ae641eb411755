//! A plugin's view of its device, over the shared client of the device's server.

use std::sync::{Arc, Mutex};

use framework::device::DeviceAccess;
use player_proto::client::{Client, ConnectionState, PendingReply, Stamped};
use player_proto::interfaces::kind::MessageKind;
use player_proto::message::Body;
use player_proto::wire::DevAddr;

/// One device on a shared client. Subscribes on creation, without waiting. A kind is read
/// and requested by its subtype on this device's own address.
pub struct ClientDevice {
    client: Arc<Client>,
    addr: DevAddr,
    subscription: Mutex<Option<PendingReply>>,
}

impl ClientDevice {
    pub fn new(client: Arc<Client>, addr: DevAddr) -> ClientDevice {
        let pending = client.subscribe_async(addr);
        ClientDevice {
            client,
            addr,
            subscription: Mutex::new(Some(pending)),
        }
    }

    fn check_subscription(&self) {
        let mut slot = self.subscription.lock().expect("subscription");
        let Some(pending) = slot.as_ref() else { return };
        if let Some(outcome) = pending.try_get() {
            if let Err(e) = outcome {
                tracing::warn!(device = %self.addr, port = self.client.port(), "subscription failed: {e}");
            }
            *slot = None;
        }
    }
}

impl DeviceAccess for ClientDevice {
    fn latest(&self, kind: MessageKind) -> Option<Stamped> {
        self.check_subscription();
        self.client.latest(self.addr, kind.subtype)
    }

    fn command(&self, body: Body) {
        self.client.command(self.addr, body);
    }

    fn request(&self, kind: MessageKind, body: Body) -> PendingReply {
        self.client.request_async(self.addr, kind.subtype, body)
    }

    fn link_state(&self) -> ConnectionState {
        self.client.state()
    }

    fn read_only(&self) -> bool {
        self.client.is_read_only()
    }
}

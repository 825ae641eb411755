//! A plugin's view of its device, over the shared client of the device's server.

use std::sync::{Arc, Mutex};

use framework::device::{DeviceAccess, LinkState, ReplyTicket, RequestFailure, Sample};
use player_proto::client::{Client, ConnectionState, PendingReply, RequestError};
use player_proto::message::Body;
use player_proto::wire::DevAddr;

/// One device on a shared client. Subscribes on creation, without waiting.
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

fn failure(e: RequestError) -> RequestFailure {
    match e {
        RequestError::Timeout(_) => RequestFailure::Timeout,
        RequestError::Disconnected(why) => RequestFailure::Disconnected(why),
        RequestError::Nack(_)
        | RequestError::AccessDenied(_)
        | RequestError::TooManyPending(_)
        | RequestError::ReadOnly(_)
        | RequestError::Untyped(_) => RequestFailure::Nack,
    }
}

impl DeviceAccess for ClientDevice {
    fn latest(&self, subtype: u8) -> Option<Sample> {
        self.check_subscription();
        self.client.latest(self.addr, subtype).map(|s| Sample {
            message: s.message,
            received: s.received,
            seq: s.seq,
        })
    }

    fn command(&self, body: Body) {
        self.client.command(self.addr, body);
    }

    fn request(&self, subtype: u8, body: Body) -> ReplyTicket {
        let pending = self.client.request_async(self.addr, subtype, body);
        ReplyTicket::polled(move || pending.try_get().map(|o| o.map(Arc::new).map_err(failure)))
    }

    fn link_state(&self) -> LinkState {
        match self.client.state() {
            ConnectionState::Connecting => LinkState::Connecting,
            ConnectionState::Connected => LinkState::Connected,
            ConnectionState::Reconnecting { attempt } => LinkState::Reconnecting { attempt },
            ConnectionState::Failed(why) => LinkState::Failed(why),
        }
    }

    fn read_only(&self) -> bool {
        self.client.is_read_only()
    }
}

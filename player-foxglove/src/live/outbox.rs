//! A Foxglove viewer's outbox: every front's bounded newest-wins queue
//! ([`player_front::outbox`]) holding the messages on the viewer's subscriptions, with
//! Foxglove's bounds. Advertisements and statuses are its control messages: never dropped.

use bytes::Bytes;
use player_front::outbox::{Bounds, Weigh};

use super::wire::SubscriptionId;

/// Messages queued per viewer before the oldest are dropped (the SDK's default is 1024):
/// about a second of everything 16 robots send at 10 Hz, more than a live view needs to ride
/// out a stall, and room for the burst of latched messages a subscription brings.
pub const MESSAGE_BACKLOG: usize = 256;
/// Bytes of messages queued per viewer before the oldest are dropped: four raw camera
/// frames. The payloads are shared by every viewer, so this bounds what one stalled viewer
/// keeps alive that the others have already sent.
pub const BACKLOG_BYTES: usize = 4 << 20;
/// Control messages queued per viewer before it is closed.
pub const CONTROL_BACKLOG: usize = 1024;

const BOUNDS: Bounds = Bounds {
    messages: MESSAGE_BACKLOG,
    bytes: BACKLOG_BYTES,
    control: CONTROL_BACKLOG,
};

/// One message on one of the viewer's subscriptions; the payload is shared.
#[derive(Debug, Clone)]
pub struct Data {
    pub subscription: SubscriptionId,
    pub log_time: u64,
    pub payload: Bytes,
}

impl Weigh for Data {
    fn weight(&self) -> usize {
        self.payload.len()
    }
}

pub type Outbox = player_front::outbox::Outbox<Data>;
pub type Batch = player_front::outbox::Batch<Data>;

/// An empty outbox with Foxglove's bounds.
pub fn viewer_outbox() -> Outbox {
    Outbox::new(BOUNDS)
}

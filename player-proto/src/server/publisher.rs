//! Publishing device data to every subscribed connection, from any thread.

use std::sync::Arc;

use super::state::ServerState;
use crate::message::{Body, Message};
use crate::wire::{DevAddr, MsgType};

/// Sends DATA messages to subscribers. Cheap to clone; never blocks on a slow client (its queue
/// fills and drops, counted, as in Player).
#[derive(Clone)]
pub struct Publisher {
    pub(crate) state: Arc<ServerState>,
}

impl Publisher {
    /// Publishes `body` as DATA of the device at `addr` (its `robot` is the port; host is filled
    /// in). Returns how many connections it was queued for.
    pub fn publish(&self, addr: DevAddr, subtype: u8, body: Body, timestamp: f64) -> usize {
        let Ok(port) = u16::try_from(addr.robot) else {
            return 0;
        };
        let full = DevAddr {
            host: self.state.host,
            ..addr
        };
        let mut message = Message::new(full, MsgType::Data, subtype, body);
        message.header.timestamp = timestamp;
        let message = Arc::new(message);
        let key = (addr.interf, addr.index);
        let mut delivered = 0;
        for session in self.state.sessions_on(port) {
            if session
                .subscriptions
                .lock()
                .expect("subscriptions")
                .contains(&key)
            {
                session.send(message.clone());
                delivered += 1;
            }
        }
        delivered
    }

    /// How many connections are subscribed to the device at `addr`.
    pub fn subscribers(&self, addr: DevAddr) -> usize {
        let key = (addr.interf, addr.index);
        let Ok(port) = u16::try_from(addr.robot) else {
            return 0;
        };
        self.state
            .sessions_on(port)
            .iter()
            .filter(|s| {
                s.subscriptions
                    .lock()
                    .expect("subscriptions")
                    .contains(&key)
            })
            .count()
    }
}

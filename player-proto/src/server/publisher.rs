//! Publishing device data to every subscribed connection, from any thread.

use std::sync::Arc;

use bytes::BytesMut;

use super::state::{ServerState, SessionState};
use crate::message::{Body, Message};
use crate::wire::{DevAddr, MsgType};

/// Sends DATA messages to subscribers. Cheap to clone; never blocks on a slow client (its queue
/// fills and drops, counted, as in Player).
#[derive(Clone)]
pub struct Publisher {
    pub(crate) state: Arc<ServerState>,
}

/// A device of a server, found once by its address ([`Publisher::find`]): publishing to it
/// and counting its subscribers then search nothing — a simulation asks both of every device
/// at every step, thousands of searches a step at 1 024 robots. Meaningful only for the server
/// that gave it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct DeviceKey(usize);

impl Publisher {
    /// Publishes `body` as DATA of the device at `addr` (its `robot` is the port; host is filled
    /// in). Returns how many connections it was queued for.
    pub fn publish(&self, addr: DevAddr, subtype: u8, body: Body, timestamp: f64) -> usize {
        self.publish_all([(addr, subtype, body, timestamp)])
    }

    /// Publishes several messages (a simulation step's data, say), then sends each
    /// connection's share in one write (from this thread with
    /// [`ServerConfig::publisher_writes`](super::ServerConfig::publisher_writes), else by
    /// waking its writer once): a client subscribed to a robot's pose and its laser gets both
    /// in one segment, one wake-up on its side instead of two. A message to a
    /// device the server does not have goes nowhere. Returns how many deliveries were queued
    /// in all.
    pub fn publish_all(
        &self,
        messages: impl IntoIterator<Item = (DevAddr, u8, Body, f64)>,
    ) -> usize {
        self.publish_to_all(
            messages
                .into_iter()
                .filter_map(|(addr, subtype, body, t)| Some((self.find(addr)?, subtype, body, t))),
        )
    }

    /// [`Publisher::publish_all`] to devices found beforehand.
    pub fn publish_to_all(
        &self,
        messages: impl IntoIterator<Item = (DeviceKey, u8, Body, f64)>,
    ) -> usize {
        let mut touched: Vec<Arc<SessionState>> = Vec::new();
        let mut delivered = 0;
        for (DeviceKey(index), subtype, body, timestamp) in messages {
            let Some(slot) = self.state.devices.get(index) else {
                continue;
            };
            let subscribers = slot.subscribers();
            if subscribers.is_empty() {
                continue;
            }
            let mut message = Message::new(slot.addr, MsgType::Data, subtype, body);
            message.header.timestamp = timestamp;
            let message = Arc::new(message);
            for session in subscribers.iter().filter(|s| !s.is_closed()) {
                session.queue_only(message.clone());
                delivered += 1;
                // A step publishes a robot's devices one after another: the same session
                // comes back in a row, and is remembered once.
                if !touched
                    .last()
                    .is_some_and(|last| Arc::ptr_eq(last, session))
                {
                    touched.push(session.clone());
                }
            }
        }
        touched.sort_unstable_by_key(Arc::as_ptr);
        touched.dedup_by(|a, b| Arc::ptr_eq(a, b));
        // Each connection's batch leaves from here in one write where the server lets the
        // publisher write and the socket takes it (`direct.rs`), else its writer is woken.
        let mut scratch = BytesMut::new();
        for session in touched {
            session.flush_now(&mut scratch);
        }
        delivered
    }

    /// The device at `addr` (its `robot` is the port), if the server has it.
    pub fn find(&self, addr: DevAddr) -> Option<DeviceKey> {
        let port = u16::try_from(addr.robot).ok()?;
        self.state
            .by_addr
            .get(&(port, addr.interf, addr.index))
            .map(|&i| DeviceKey(i))
    }

    /// How many connections are subscribed to the device at `addr` (one that is closing
    /// counts until it has left).
    pub fn subscribers(&self, addr: DevAddr) -> usize {
        self.find(addr).map_or(0, |key| self.subscribers_of(key))
    }

    /// [`Publisher::subscribers`] of a device found beforehand. It reads the device's list
    /// alone: looking into each connection was a cache miss each, for every device at every
    /// step of a simulation.
    pub fn subscribers_of(&self, DeviceKey(index): DeviceKey) -> usize {
        self.state
            .devices
            .get(index)
            .map_or(0, |slot| slot.subscribers().len())
    }
}

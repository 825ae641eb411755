//! A device of the robot, as the relay serves it downstream: subscriptions, commands and
//! requests go up to the robot over the relay's one connection; the server in front has
//! already refused what an observer may not send, so whatever reaches here may go.

use std::sync::Arc;

use player_proto::client::{Client, RequestError};
use player_proto::message::Message;
use player_proto::server::{Device, Reply};
use player_proto::wire::DevAddr;

use crate::subscriptions::Subscriptions;

pub(crate) struct RelayedDevice {
    pub upstream: Arc<Client>,
    /// The device's address on the robot's server.
    pub addr: DevAddr,
    pub driver: String,
    /// The robot's upstream subscriptions, shared with the fronts' looks and every
    /// incarnation of its downstream server.
    pub subscribed: Arc<Subscriptions>,
}

impl Device for RelayedDevice {
    fn driver_name(&self) -> &str {
        &self.driver
    }

    /// The first observer of a device subscribes the relay to it upstream; the subscription is
    /// kept after the last one leaves (cheap next to reconnecting for the next observer).
    fn on_subscribe(&mut self) -> bool {
        // The grant arrives on the robot thread; data flows from then on.
        self.subscribed.observe((self.addr.interf, self.addr.index));
        true
    }

    fn on_command(&mut self, command: &Message) {
        if let Err(e) = self.upstream.try_command(self.addr, command.body.clone()) {
            tracing::warn!(device = %self.addr, "command not relayed: {e}");
        }
    }

    /// Blocks this server worker for the robot's answer; `block_in_place` lets the runtime
    /// move the other connections' work to another worker meanwhile.
    fn on_request(&mut self, request: &Message) -> Reply {
        let (upstream, addr) = (&self.upstream, self.addr);
        let outcome = tokio::task::block_in_place(|| {
            upstream.request(addr, request.header.subtype, request.body.clone())
        });
        match outcome {
            Ok(reply) => Reply::Ack(reply.body),
            Err(RequestError::Nack(_)) => Reply::Nack,
            Err(e) => {
                tracing::warn!(device = %addr, "request not answered upstream: {e}");
                Reply::Nack
            }
        }
    }
}

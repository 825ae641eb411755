//! The device side of a server: what a mock or simulated device implements.

use crate::message::{Body, Message};

/// A device's answer to a request. Short-lived (returned and sent at once), so the size of
/// the body variant does not matter.
#[derive(Debug, Clone, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum Reply {
    /// ACK with this body (`Body::Empty` for an empty ACK).
    Ack(Body),
    /// Empty NACK: not handled, or failed.
    Nack,
}

/// A device served on a port. Every method has a default, so a mock that only publishes data
/// is a few lines; requests it does not handle are NACKed, as Player's drivers do.
pub trait Device: Send + 'static {
    /// The driver name reported by DRIVERINFO and in subscription replies.
    fn driver_name(&self) -> &str;

    /// A client subscribes. Returning `false` refuses it (the ACK carries access 3, as when a
    /// Player driver fails to start).
    fn on_subscribe(&mut self) -> bool {
        true
    }

    /// Data a new subscriber is sent at once, after its subscription's ACK: (subtype, body,
    /// timestamp). None by default, as in Player, where data comes with the driver's next
    /// update; a lockstep simulation, which does not step until its clients command, sends
    /// what it has now, so that a program can read before its first command.
    fn greeting(&mut self) -> Vec<(u8, Body, f64)> {
        Vec::new()
    }

    /// A client unsubscribed or went away.
    fn on_unsubscribe(&mut self) {}

    /// A command from a client.
    fn on_command(&mut self, _command: &Message) {}

    /// Whether this device takes commands. One that does not (a replayed recording) has each
    /// command answered with a NACK, which Player never sends for commands, so a client learns
    /// that its command went nowhere instead of it being silently eaten.
    fn accepts_commands(&self) -> bool {
        true
    }

    /// A request from a client; its header says which (subtype) and the body carries the data.
    fn on_request(&mut self, _request: &Message) -> Reply {
        Reply::Nack
    }
}

//! Who may act on a server's devices. Player lets every connection command every device; a
//! server that fans one robot out to many watchers (a relay, a classroom demo) must not, so
//! it names its commanders and treats everyone else as an observer, who may send only what
//! [`crate::access::observer_may_send`] allows. A refused request is NACKed, as an unhandled
//! one is in Player; a refused command is dropped (Player never acknowledges commands, so a
//! NACK would be a reply to nothing).

use std::net::IpAddr;
use std::sync::Mutex;

use crate::access::observer_may_send;
use crate::message::Message;

/// Which connections may command devices and send them configuration requests.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Commanders {
    /// Every connection, as in Player.
    #[default]
    Everyone,
    /// No connection: every client only observes.
    Nobody,
    /// Connections from this address (a designated controller's machine).
    Address(IpAddr),
    /// The first connection that commands or configures; control passes on when it closes.
    FirstToAsk,
}

/// A connection as the gate knows it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Peer {
    /// Unique per connection for the server's lifetime.
    pub id: u64,
    pub ip: IpAddr,
}

/// The server's gate: its policy and, for [`Commanders::FirstToAsk`], who holds control.
#[derive(Debug, Default)]
pub struct CommandGate {
    policy: Commanders,
    holder: Mutex<Option<u64>>,
}

impl CommandGate {
    pub fn new(policy: Commanders) -> CommandGate {
        CommandGate {
            policy,
            holder: Mutex::new(None),
        }
    }

    /// May `peer` send `message` to a device?
    pub fn admits(&self, peer: Peer, message: &Message) -> bool {
        if observer_may_send(message) {
            return true;
        }
        match self.policy {
            Commanders::Everyone => true,
            Commanders::Nobody => false,
            Commanders::Address(ip) => peer.ip == ip,
            Commanders::FirstToAsk => {
                let mut holder = self.holder.lock().unwrap_or_else(|e| e.into_inner());
                *holder.get_or_insert(peer.id) == peer.id
            }
        }
    }

    /// A connection closed: control it held is free again.
    pub fn left(&self, peer: Peer) {
        let mut holder = self.holder.lock().unwrap_or_else(|e| e.into_inner());
        if *holder == Some(peer.id) {
            *holder = None;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interfaces::position2d::{Position2d, Position2dCmdVel};
    use crate::interfaces::{laser, player};
    use crate::message::Body;
    use crate::wire::{DevAddr, Interface, MsgType};
    use std::net::Ipv4Addr;

    fn drive() -> Message {
        Message::typed(
            DevAddr::local(Interface::POSITION2D, 0),
            MsgType::Cmd,
            Position2d::Velocity(Position2dCmdVel::default()),
        )
    }

    fn peer(id: u64, last: u8) -> Peer {
        Peer {
            id,
            ip: IpAddr::V4(Ipv4Addr::new(127, 0, 0, last)),
        }
    }

    #[test]
    fn observers_read_and_only_commanders_act() {
        let geometry = Message::new(
            DevAddr::local(Interface::LASER, 0),
            MsgType::Req,
            laser::REQ_GET_GEOM,
            Body::Empty,
        );
        let subscribe = Message::new(
            DevAddr::local(Interface::PLAYER, 0),
            MsgType::Req,
            player::REQ_DEV,
            Body::Empty,
        );
        let nobody = CommandGate::new(Commanders::Nobody);
        assert!(nobody.admits(peer(1, 1), &geometry));
        assert!(nobody.admits(peer(1, 1), &subscribe));
        assert!(!nobody.admits(peer(1, 1), &drive()));
        assert!(CommandGate::new(Commanders::Everyone).admits(peer(1, 1), &drive()));
        let one = CommandGate::new(Commanders::Address(peer(0, 2).ip));
        assert!(one.admits(peer(7, 2), &drive()));
        assert!(!one.admits(peer(8, 1), &drive()));
    }

    #[test]
    fn the_first_to_command_holds_control_until_it_leaves() {
        let gate = CommandGate::new(Commanders::FirstToAsk);
        assert!(gate.admits(peer(2, 1), &drive()));
        assert!(gate.admits(peer(2, 1), &drive()));
        assert!(!gate.admits(peer(3, 1), &drive()));
        gate.left(peer(3, 1));
        assert!(
            !gate.admits(peer(3, 1), &drive()),
            "an observer leaving frees nothing"
        );
        gate.left(peer(2, 1));
        assert!(gate.admits(peer(3, 1), &drive()));
    }
}

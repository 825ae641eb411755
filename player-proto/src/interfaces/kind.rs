//! Names for messages, so that code above the wire never writes a subtype number.
//!
//! The interface tables (`interface_messages!`) give every (class, subtype) a Player name;
//! from the same table the macro generates the interface's list of [`MessageKind`]s here, and
//! one typed constant per entry (`Laser::REQ_GET_GEOM`, a `crate::body_kind::BodyKind`), so the
//! number lives in the table and nowhere else. What a kind knows of bodies lives above the
//! message enum, in `crate::body_kind`.

use std::fmt;

use crate::wire::{Header, Interface, MessageClass};

/// One message of the protocol: the interface, class and subtype that name it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct MessageKind {
    pub interf: Interface,
    pub class: MessageClass,
    pub subtype: u8,
}

impl MessageKind {
    /// Whether `header` carries a message of this kind (any reply type of a request: REQ,
    /// ACK and NACK share the request's subtype).
    pub fn matches(&self, header: &Header) -> bool {
        header.addr.interf == self.interf
            && header.subtype == self.subtype
            && header.msg_type.class() == self.class
    }

    /// The DATA kinds an interface defines, in table order (none for an interface this crate
    /// does not decode).
    pub fn data_of(interf: Interface) -> impl Iterator<Item = MessageKind> {
        MessageKind::all_of(interf)
            .iter()
            .copied()
            .filter(|k| k.class == MessageClass::Data)
    }
}

impl fmt::Display for MessageKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {:?} {}", self.interf, self.class, self.subtype)
    }
}

/// An interface's message enum together with the interface it belongs to.
pub trait InterfaceMessages {
    const INTERFACE: Interface;
    /// Every message of the interface's table, in table order.
    const KINDS: &'static [MessageKind];
}

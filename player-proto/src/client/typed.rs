//! Reads and requests named by the message rather than by its subtype number: the subtype
//! and the body type both come from a [`BodyKind`] (or a [`DataBody`] type), so a caller gets
//! the structure it asked for or an error, never a body to match by hand.

use super::{Client, PendingReply, RequestError, Stamped};
use crate::body_kind::{BodyKind, DataBody};
use crate::message::{Body, Message};
use crate::wire::DevAddr;

impl Client {
    /// The newest DATA message whose body is a `T`, with the body, e.g.
    /// `client.latest_of::<LaserScan>(addr)`.
    pub fn latest_of<T: DataBody>(&self, addr: DevAddr) -> Option<(T, Stamped)> {
        self.latest_kind(addr, T::KIND)
    }

    /// The newest DATA message of `kind`, with its body.
    pub fn latest_kind<T: Clone>(&self, addr: DevAddr, kind: BodyKind<T>) -> Option<(T, Stamped)> {
        let stamped = self.latest(addr, kind.subtype())?;
        let body = kind.of(&stamped.message)?.clone();
        Some((body, stamped))
    }

    /// Asks for the structure a "get" request of `kind` returns (the request body is empty)
    /// without waiting; read the reply with [`BodyKind::reply_of`].
    pub fn fetch_async<T>(&self, addr: DevAddr, kind: BodyKind<T>) -> PendingReply {
        self.request_async(addr, kind.subtype(), Body::Empty)
    }

    /// Asks for the structure a "get" request of `kind` returns, and waits for it.
    pub fn fetch<T: Clone>(&self, addr: DevAddr, kind: BodyKind<T>) -> Result<T, RequestError> {
        let reply = self.request(addr, kind.subtype(), Body::Empty)?;
        kind.reply_of(&reply)
    }

    /// Sends a request of `kind` carrying `value` ("set" requests) and waits for the ACK.
    pub fn request_with<T>(
        &self,
        addr: DevAddr,
        kind: BodyKind<T>,
        value: T,
    ) -> Result<Message, RequestError> {
        self.request(addr, kind.subtype(), kind.to_body(value))
    }
}

impl<T: Clone> BodyKind<T> {
    /// The structure a reply of this kind carries. An ACK with another body is treated as a
    /// refusal (`Nack`, carrying the reply), since the request's promise was not kept.
    pub fn reply_of(&self, reply: &Message) -> Result<T, RequestError> {
        self.of(reply)
            .cloned()
            .ok_or_else(|| RequestError::Nack(Box::new(reply.clone())))
    }
}

#[cfg(test)]
mod tests {
    use crate::interfaces::laser::{Laser, LaserGeometry};
    use crate::message::{Body, Message};
    use crate::wire::{DevAddr, MsgType};

    #[test]
    fn a_reply_yields_its_structure_or_a_refusal() {
        let addr: DevAddr = "laser:0".parse().unwrap();
        let geometry = LaserGeometry::default();
        let ack = Message::typed(addr, MsgType::Ack, Laser::Geometry(geometry.clone()));
        assert_eq!(Laser::REQ_GET_GEOM.reply_of(&ack), Ok(geometry));
        let geometry = Laser::REQ_GET_GEOM.subtype();
        let empty = Message::new(addr, MsgType::Ack, geometry, Body::Empty);
        assert!(Laser::REQ_GET_GEOM.reply_of(&empty).is_err());
        assert!(
            Laser::REQ_GET_CONFIG.reply_of(&ack).is_err(),
            "same interface, other request"
        );
    }
}

//! What a robot's server told the relay about its devices, kept for the Zenoh side to answer
//! from: the device list and driver names (`…/devices`), and the replies to the requests that
//! only read a device — geometries, configurations, map info and tiles (`…/replies`). The
//! relay's own survey asks those on every connection, so the cache fills by itself.
//!
//! Player answers a device's requests in order, so each reply is paired with the oldest
//! unanswered request of the same device and subtype; the request's body is kept with it,
//! which tells apart replies to one subtype asked with different arguments (map tiles).

use std::collections::{HashMap, VecDeque};

use bytes::{Bytes, BytesMut};
use player_proto::access::observer_may_send;
use player_proto::capture::Direction;
use player_proto::interfaces::player::{self, Player};
use player_proto::message::{Body, Message};
use player_proto::wire::{Header, Interface, MsgType};

/// A reply that describes a device, with the request it answers.
#[derive(Debug, Clone, PartialEq)]
pub struct CachedReply {
    pub subtype: u8,
    /// The request's body, as sent.
    pub request: Bytes,
    /// The whole reply as it came from the robot: header and body.
    pub reply: Bytes,
}

type DeviceKey = (Interface, u16);

/// One robot's cache, for one connection (cleared when it reconnects).
#[derive(Debug, Default)]
pub struct ReplyCache {
    devlist: Option<Bytes>,
    expected_devices: usize,
    driverinfo: Vec<Bytes>,
    pending: HashMap<(Interface, u16, u8), VecDeque<Bytes>>,
    replies: HashMap<DeviceKey, Vec<CachedReply>>,
}

/// A message's wire bytes from the tap's header and body.
pub fn wire_bytes(header: &Header, body: &Bytes) -> Bytes {
    let mut out = BytesMut::with_capacity(player_proto::wire::HEADER_LEN + body.len());
    header.encode(&mut out);
    out.extend_from_slice(body);
    out.freeze()
}

impl ReplyCache {
    /// Forgets everything: a new connection may serve other devices.
    pub fn clear(&mut self) {
        *self = ReplyCache::default();
    }

    /// Takes in one frame the relay's client sent or received.
    pub fn observe(&mut self, direction: Direction, header: &Header, body: &Bytes) {
        let key = (header.addr.interf, header.addr.index, header.subtype);
        match (direction, header.msg_type) {
            (Direction::ClientToServer, MsgType::Req) => {
                if header.addr.interf == Interface::PLAYER {
                    return;
                }
                let Ok(request) = Message::decode(*header, body.clone()) else {
                    return;
                };
                if observer_may_send(&request) {
                    self.pending.entry(key).or_default().push_back(body.clone());
                }
            }
            (Direction::ServerToClient, MsgType::Ack)
                if header.addr.interf == Interface::PLAYER =>
            {
                self.observe_player_reply(header, body);
            }
            (Direction::ServerToClient, MsgType::Ack | MsgType::Nack) => {
                let Some(request) = self.pending.get_mut(&key).and_then(VecDeque::pop_front) else {
                    return;
                };
                if header.msg_type == MsgType::Nack {
                    return;
                }
                let cached = CachedReply {
                    subtype: header.subtype,
                    request,
                    reply: wire_bytes(header, body),
                };
                let replies = self
                    .replies
                    .entry((header.addr.interf, header.addr.index))
                    .or_default();
                replies.retain(|r| (r.subtype, &r.request) != (cached.subtype, &cached.request));
                replies.push(cached);
            }
            _ => {}
        }
    }

    fn observe_player_reply(&mut self, header: &Header, body: &Bytes) {
        match header.subtype {
            player::REQ_DEVLIST => {
                if let Ok(Message {
                    body: Body::Player(Player::DevList(list)),
                    ..
                }) = Message::decode(*header, body.clone())
                {
                    self.expected_devices = list.devices.len();
                    self.devlist = Some(wire_bytes(header, body));
                    self.driverinfo.clear();
                }
            }
            player::REQ_DRIVERINFO if self.devlist.is_some() => {
                self.driverinfo.push(wire_bytes(header, body));
            }
            _ => {}
        }
    }

    /// Whether the device list and every driver name are in: the robot can be announced.
    pub fn ready(&self) -> bool {
        self.devlist.is_some() && self.driverinfo.len() >= self.expected_devices
    }

    /// The device list reply, then each driver-info reply.
    pub fn devices(&self) -> Vec<Bytes> {
        self.devlist
            .iter()
            .chain(&self.driverinfo)
            .cloned()
            .collect()
    }

    /// The replies describing one device.
    pub fn replies(&self, interf: Interface, index: u16) -> &[CachedReply] {
        self.replies
            .get(&(interf, index))
            .map_or(&[], Vec::as_slice)
    }
}

impl ReplyCache {
    /// Every device with cached replies.
    pub fn devices_described(&self) -> impl Iterator<Item = (Interface, u16, &[CachedReply])> {
        self.replies
            .iter()
            .map(|((interf, index), replies)| (*interf, *index, replies.as_slice()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use player_proto::interfaces::laser;
    use player_proto::wire::DevAddr;

    fn header(msg_type: MsgType, subtype: u8, size: u32) -> Header {
        Header {
            addr: DevAddr {
                host: 0,
                robot: 6665,
                interf: Interface::LASER,
                index: 0,
            },
            msg_type,
            subtype,
            timestamp: 1.5,
            seq: 0,
            size,
        }
    }

    #[test]
    fn a_reply_is_kept_with_the_request_it_answers() {
        let mut cache = ReplyCache::default();
        let empty = Bytes::new();
        let ask = header(MsgType::Req, laser::REQ_GET_GEOM, 0);
        cache.observe(Direction::ClientToServer, &ask, &empty);
        let body = Bytes::from_static(&[0; 40]);
        let ack = header(MsgType::Ack, laser::REQ_GET_GEOM, 40);
        cache.observe(Direction::ServerToClient, &ack, &body);
        let replies = cache.replies(Interface::LASER, 0);
        assert_eq!(replies.len(), 1);
        assert_eq!(replies[0].reply.len(), 80);
        // A reply nobody asked for (or asked twice) is not kept twice.
        cache.observe(Direction::ServerToClient, &ack, &body);
        assert_eq!(cache.replies(Interface::LASER, 0).len(), 1);
        assert!(!cache.ready());
    }
}

//! Message kinds that know their body type: a reader gets the typed body out of a
//! [`Body`], and a sender cannot pair a subtype with the wrong structure. Above the message
//! enum, which holds every interface's bodies; the plain names are
//! [`crate::interfaces::kind`].

use std::fmt;

use crate::interfaces::kind::MessageKind;
use crate::message::{Body, DecodeError, Message};
use crate::wire::xdr_view::view_all;
use crate::wire::{Header, View, XdrView};

/// A [`MessageKind`] that also knows the body type its messages carry, so a reader gets the
/// typed body and a sender cannot pair a subtype with the wrong structure.
pub struct BodyKind<T> {
    kind: MessageKind,
    peek: fn(&Body) -> Option<&T>,
    wrap: fn(T) -> Body,
}

// Manual impls: a derive would ask `T: Clone`, though only function pointers are held.
impl<T> Clone for BodyKind<T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<T> Copy for BodyKind<T> {}

impl<T> fmt::Debug for BodyKind<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "BodyKind({})", self.kind)
    }
}

impl<T> BodyKind<T> {
    /// Used by `interface_messages!`; `peek` and `wrap` must agree with `kind`.
    pub(crate) const fn new(
        kind: MessageKind,
        peek: fn(&Body) -> Option<&T>,
        wrap: fn(T) -> Body,
    ) -> BodyKind<T> {
        BodyKind { kind, peek, wrap }
    }

    pub const fn kind(&self) -> MessageKind {
        self.kind
    }

    pub const fn subtype(&self) -> u8 {
        self.kind.subtype
    }

    /// The typed body, when `body` is one of this kind.
    pub fn body_of<'a>(&self, body: &'a Body) -> Option<&'a T> {
        (self.peek)(body)
    }

    /// The typed body of `message`, when its header names this kind and its body decoded as
    /// such.
    pub fn of<'a>(&self, message: &'a Message) -> Option<&'a T> {
        if !self.kind.matches(&message.header) {
            return None;
        }
        self.body_of(&message.body)
    }

    /// `value` as a message body of this kind.
    pub fn to_body(&self, value: T) -> Body {
        (self.wrap)(value)
    }
}

impl<T: XdrView> BodyKind<T> {
    /// The body of a message of this kind read in place (see [`crate::wire::xdr_view`]):
    /// `None` when `header` names another kind or the body is empty (a "get" request, which
    /// decodes as [`Body::Empty`]), the decoder's own error when the body is not one. For code
    /// that looks at a message and lets it go; bytes after the body are let be.
    // Inlined: a view is a few numbers and slices, built best in the caller's registers;
    // returned through memory from a call, copying it out cost as much as making it.
    #[inline(always)]
    pub fn view<'a>(
        &self,
        header: &Header,
        body: &'a [u8],
    ) -> Option<Result<View<'a, T>, DecodeError>> {
        if !self.kind.matches(header) || body.is_empty() {
            return None;
        }
        Some(view_all::<T>(body).map_err(|err| DecodeError::from_xdr(*header, body, err)))
    }
}

/// A body type sent as DATA: it names its own kind, so `latest_of::<LaserScan>()` needs no
/// subtype. (Requests share structures between their get and set forms, so they are named by
/// their [`BodyKind`] constant instead.)
pub trait DataBody: Clone + Sized + 'static {
    const KIND: BodyKind<Self>;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interfaces::kind::InterfaceMessages;
    use crate::interfaces::laser::{self, Laser, LaserGeometry, LaserScan};
    use crate::interfaces::{
        bumper, camera, fiducial, gripper, ir, localize, map, planner, player, position2d, ptz,
        ranger, sonar,
    };
    use crate::wire::{DevAddr, MsgType};
    use crate::wire::{Interface, MessageClass};
    use bytes::Bytes;

    #[test]
    fn the_protocol_constants_agree_with_the_tables() {
        let pairs = [
            (laser::REQ_GET_GEOM, Laser::REQ_GET_GEOM.subtype()),
            (laser::REQ_GET_CONFIG, Laser::REQ_GET_CONFIG.subtype()),
            (laser::REQ_GET_ID, Laser::REQ_GET_ID.subtype()),
            (bumper::REQ_GET_GEOM, bumper::Bumper::REQ_GET_GEOM.subtype()),
            (gripper::CMD_OPEN, gripper::Gripper::CMD_OPEN.subtype()),
            (gripper::CMD_CLOSE, gripper::Gripper::CMD_CLOSE.subtype()),
            (gripper::CMD_STOP, gripper::Gripper::CMD_STOP.subtype()),
            (gripper::CMD_STORE, gripper::Gripper::CMD_STORE.subtype()),
            (
                gripper::CMD_RETRIEVE,
                gripper::Gripper::CMD_RETRIEVE.subtype(),
            ),
            (
                camera::REQ_GET_SOURCE,
                camera::Camera::REQ_GET_SOURCE.subtype(),
            ),
            (
                camera::REQ_GET_IMAGE,
                camera::Camera::REQ_GET_IMAGE.subtype(),
            ),
            (
                fiducial::REQ_GET_GEOM,
                fiducial::Fiducial::REQ_GET_GEOM.subtype(),
            ),
            (
                fiducial::REQ_GET_FOV,
                fiducial::Fiducial::REQ_GET_FOV.subtype(),
            ),
            (
                fiducial::REQ_GET_ID,
                fiducial::Fiducial::REQ_GET_ID.subtype(),
            ),
            (map::REQ_GET_INFO, map::Map::REQ_GET_INFO.subtype()),
            (map::REQ_GET_DATA, map::Map::REQ_GET_DATA.subtype()),
            (map::REQ_GET_VECTOR, map::Map::REQ_GET_VECTOR.subtype()),
            (player::REQ_DEVLIST, player::Player::REQ_DEVLIST.subtype()),
            (
                player::REQ_DRIVERINFO,
                player::Player::REQ_DRIVERINFO.subtype(),
            ),
            (player::REQ_DEV, player::Player::REQ_DEV.subtype()),
            (player::REQ_DATAMODE, player::Player::REQ_DATAMODE.subtype()),
            (player::REQ_AUTH, player::Player::REQ_AUTH.subtype()),
            (
                player::REQ_NAMESERVICE,
                player::Player::REQ_NAMESERVICE.subtype(),
            ),
            (
                player::REQ_ADD_REPLACE_RULE,
                player::Player::REQ_ADD_REPLACE_RULE.subtype(),
            ),
            (
                position2d::REQ_GET_GEOM,
                position2d::Position2d::REQ_GET_GEOM.subtype(),
            ),
            (ranger::REQ_GET_GEOM, ranger::Ranger::REQ_GET_GEOM.subtype()),
            (
                ranger::REQ_GET_CONFIG,
                ranger::Ranger::REQ_GET_CONFIG.subtype(),
            ),
            (sonar::REQ_GET_GEOM, sonar::Sonar::REQ_GET_GEOM.subtype()),
            (
                localize::REQ_GET_PARTICLES,
                localize::Localize::REQ_GET_PARTICLES.subtype(),
            ),
            (
                planner::REQ_GET_WAYPOINTS,
                planner::Planner::REQ_GET_WAYPOINTS.subtype(),
            ),
            (ptz::REQ_GEOM, ptz::Ptz::REQ_GEOM.subtype()),
            (ptz::REQ_STATUS, ptz::Ptz::REQ_STATUS.subtype()),
            (ir::REQ_POSE, ir::Ir::REQ_POSE.subtype()),
        ];
        for (i, (named, generated)) in pairs.into_iter().enumerate() {
            assert_eq!(named, generated, "pair {i}");
        }
    }

    #[test]
    fn every_listed_kind_is_a_row_of_its_table() {
        let mut listed = 0;
        for (interf, _) in Interface::KNOWN {
            for kind in MessageKind::all_of(*interf) {
                assert_eq!(kind.interf, *interf);
                let header = Header {
                    addr: DevAddr::local(kind.interf, 0),
                    msg_type: kind.class.default_type(),
                    subtype: kind.subtype,
                    timestamp: 0.0,
                    seq: 0,
                    size: 0,
                };
                // An unknown row decodes to raw bytes; a known one to its structure or an
                // error about it.
                let decoded = Message::decode(header, Bytes::from(vec![0u8; 64]));
                assert!(
                    !matches!(
                        decoded,
                        Ok(Message {
                            body: Body::Unknown(_),
                            ..
                        })
                    ),
                    "{kind} is listed but not decoded"
                );
                listed += 1;
            }
        }
        assert_eq!(Laser::KINDS.len(), 9);
        assert!(listed > 80, "every implemented interface lists its kinds");
    }

    #[test]
    fn data_kinds_are_the_data_rows_of_the_table() {
        let laser_data: Vec<u8> = MessageKind::data_of(Interface::LASER)
            .map(|k| k.subtype)
            .collect();
        assert_eq!(laser_data, [1, 2, 3]);
        let ranger_data = MessageKind::data_of(Interface::RANGER).count();
        assert_eq!(ranger_data, 5);
        assert_eq!(
            MessageKind::data_of(Interface::AUDIO).count(),
            0,
            "not decoded"
        );
    }

    #[test]
    fn a_body_kind_reads_only_its_own_messages() {
        let addr: DevAddr = "laser:0".parse().unwrap();
        let scan = LaserScan {
            ranges: vec![1.5],
            ..Default::default()
        };
        let message = Message::typed(addr, MsgType::Data, Laser::Scan(scan.clone()));
        assert_eq!(LaserScan::KIND.of(&message), Some(&scan));
        assert_eq!(Laser::DATA_SCANPOSE.of(&message), None, "another subtype");
        let sonar: DevAddr = "sonar:0".parse().unwrap();
        let elsewhere = Message::typed(sonar, MsgType::Data, Laser::Scan(scan.clone()));
        assert_eq!(LaserScan::KIND.of(&elsewhere), None, "another interface");

        let body = Laser::REQ_GET_GEOM.to_body(LaserGeometry::default());
        assert_eq!(
            body.kind(),
            Some((MessageClass::Request, laser::REQ_GET_GEOM))
        );
        assert!(Laser::REQ_GET_GEOM.body_of(&body).is_some());
    }
}

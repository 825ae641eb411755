//! What an observer may send: the line between watching a robot and acting on it.
//!
//! Player 3 has no read-only access on the wire: a subscription is OPEN or CLOSE (the READ,
//! WRITE and ALL modes of Player 2 are gone), and any connected client may command any device
//! or change its configuration. So "read-only" is decided per message, by the sender (a
//! read-only [`crate::client::Client`] refuses the rest before it reaches the socket) or by a
//! server that lets only one client command (a relay NACKs the rest).
//!
//! An observer may send the `player` interface's requests, which only read or shape its own
//! connection (device list, driver info, subscribe and unsubscribe, data mode, data requests,
//! replace rules), and the requests that only read a device (the `GET_*` requests:
//! geometry, configuration, identity, images, maps) — a viewer needs those to draw what it
//! sees. Commands, and every other request, act on the robot.

use crate::interfaces::{
    bumper, camera, fiducial, gripper, laser, map, player, position2d, ranger, sonar,
};
use crate::message::Message;
use crate::wire::{Interface, MsgType};

/// Requests that only read, by interface and subtype.
const READING_REQUESTS: &[(Interface, &[u8])] = &[
    (
        Interface::PLAYER,
        &[
            player::REQ_DEVLIST,
            player::REQ_DRIVERINFO,
            player::REQ_DEV,
            player::REQ_DATA,
            player::REQ_DATAMODE,
            player::REQ_ADD_REPLACE_RULE,
        ],
    ),
    (
        Interface::LASER,
        &[
            laser::REQ_GET_GEOM,
            laser::REQ_GET_CONFIG,
            laser::REQ_GET_ID,
        ],
    ),
    (Interface::POSITION2D, &[position2d::REQ_GET_GEOM]),
    (Interface::SONAR, &[sonar::REQ_GET_GEOM]),
    (Interface::BUMPER, &[bumper::REQ_GET_GEOM]),
    (Interface::GRIPPER, &[gripper::REQ_GET_GEOM]),
    (
        Interface::RANGER,
        &[ranger::REQ_GET_GEOM, ranger::REQ_GET_CONFIG],
    ),
    (
        Interface::FIDUCIAL,
        &[
            fiducial::REQ_GET_GEOM,
            fiducial::REQ_GET_FOV,
            fiducial::REQ_GET_ID,
        ],
    ),
    (
        Interface::CAMERA,
        &[camera::REQ_GET_SOURCE, camera::REQ_GET_IMAGE],
    ),
    (
        Interface::MAP,
        &[map::REQ_GET_INFO, map::REQ_GET_DATA, map::REQ_GET_VECTOR],
    ),
];

/// May an observer (a client that must not act on the robot) send this message?
pub fn observer_may_send(message: &Message) -> bool {
    let h = &message.header;
    h.msg_type == MsgType::Req
        && READING_REQUESTS
            .iter()
            .any(|(interf, subtypes)| *interf == h.addr.interf && subtypes.contains(&h.subtype))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interfaces::position2d::{Position2d, Position2dCmdVel};
    use crate::message::Body;
    use crate::wire::DevAddr;

    fn to(interf: Interface, msg_type: MsgType, subtype: u8) -> Message {
        Message::new(DevAddr::local(interf, 0), msg_type, subtype, Body::Empty)
    }

    #[test]
    fn reading_requests_pass_and_acting_ones_do_not() {
        for subtype in [player::REQ_DEVLIST, player::REQ_DEV, player::REQ_DATAMODE] {
            assert!(observer_may_send(&to(
                Interface::PLAYER,
                MsgType::Req,
                subtype
            )));
        }
        assert!(observer_may_send(&to(
            Interface::LASER,
            MsgType::Req,
            laser::REQ_GET_GEOM
        )));
        // AUTH is no read; SET_CONFIG (2) and RESET_ODOM change the robot.
        assert!(!observer_may_send(&to(
            Interface::PLAYER,
            MsgType::Req,
            player::REQ_AUTH
        )));
        assert!(!observer_may_send(&to(Interface::LASER, MsgType::Req, 2)));
        assert!(!observer_may_send(&to(
            Interface::POSITION2D,
            MsgType::Req,
            position2d::REQ_RESET_ODOM
        )));
        // A command never passes, even with a subtype that reads elsewhere.
        assert!(!observer_may_send(&to(Interface::PLAYER, MsgType::Cmd, 1)));
        let drive = Message::typed(
            DevAddr::local(Interface::POSITION2D, 0),
            MsgType::Cmd,
            Position2d::Velocity(Position2dCmdVel::default()),
        );
        assert!(!observer_may_send(&drive));
    }
}

//! Commands and requests coming back from Zenoh to a robot of the front.
//!
//! Commands arrive as puts on `…/<interface>/<index>/cmd`, requests as queries on the same
//! key (payload: the raw Player message; attachment: a [`Stamp`]). The rule, one controller
//! per robot:
//!
//! * a command reaches the robot only from the front's controller, and only fresh (see
//!   [`crate::stamp::MAX_COMMAND_AGE`]); anything else is logged and counted, never queued;
//! * a request that only reads (`GET_*`, see `player_proto::access`) is answered for anyone;
//!   any other request only for the controller — everyone else gets a NACK, as a Player
//!   server answers a request it will not handle.

use std::sync::Arc;
use std::sync::atomic::Ordering;
use std::time::{Duration, SystemTime};

use bytes::Bytes;
use player_proto::access::observer_may_send;
use player_proto::message::{Body, Message};
use player_proto::wire::{HEADER_LEN, Header, MsgType};
use zenoh::Wait;
use zenoh::bytes::ZBytes;
use zenoh::pubsub::Subscriber;
use zenoh::query::{Query, Queryable};

use crate::error::ZenohError;
use crate::keys::{Leaf, RobotKey, device_of_key, every_device};
use crate::shared::FrontShared;
use crate::stamp::Stamp;

/// How long the robot has to answer a request from Zenoh.
const REQUEST_WAIT: Duration = Duration::from_secs(3);

/// Why a command or request was not passed on.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum Refusal {
    #[error("no sender stamp")]
    NoStamp,
    #[error("stale: sent {0:?} ago")]
    Stale(Duration),
    #[error("{0:?} is not this robot's controller")]
    NotController(String),
    #[error("not a Player {0:?} message")]
    Malformed(MsgType),
}

/// Whether `message`, stamped `stamp`, may act on the robot of a front controlled by
/// `controller`.
pub fn authorise(
    controller: Option<&str>,
    stamp: Option<&Stamp>,
    message: &Message,
    now: SystemTime,
) -> Result<(), Refusal> {
    let stamp = stamp.ok_or(Refusal::NoStamp)?;
    if !stamp.is_fresh(now) {
        return Err(Refusal::Stale(stamp.age(now)));
    }
    if message.header.msg_type == MsgType::Req && observer_may_send(message) {
        return Ok(());
    }
    if controller == Some(stamp.sender.as_str()) {
        Ok(())
    } else {
        Err(Refusal::NotController(stamp.sender.clone()))
    }
}

/// A Player message from a payload: header, then exactly `size` body bytes.
pub fn decode_raw(raw: &[u8]) -> Option<Message> {
    let header = Header::decode_slice(raw)?.ok()?;
    let body = raw.get(HEADER_LEN..)?;
    (body.len() == header.size as usize).then_some(())?;
    Message::decode(header, Bytes::copy_from_slice(body)).ok()
}

fn stamp_of(attachment: Option<&ZBytes>) -> Option<Stamp> {
    Stamp::decode(&attachment?.to_bytes())
}

/// The subscriber taking commands for every robot of the site.
pub(crate) fn declare_commands(shared: &Arc<FrontShared>) -> Result<Subscriber<()>, ZenohError> {
    let handler = shared.clone();
    Ok(shared
        .session
        .declare_subscriber(every_device(&shared.config.site, Leaf::Cmd))
        .callback(move |sample| {
            let key = sample.key_expr().as_str();
            let (Some(robot), Some((interf, index, _))) =
                (RobotKey::of_key(key), device_of_key(key))
            else {
                return;
            };
            // Another relay's robot on the same site: not ours to refuse.
            let Some(client) = handler.client(&robot) else {
                return;
            };
            let stamp = stamp_of(sample.attachment());
            let verdict = match decode_raw(&sample.payload().to_bytes()) {
                Some(m) if m.header.msg_type == MsgType::Cmd => {
                    handler_verdict(&handler, stamp.as_ref(), &m).map(|()| m)
                }
                Some(m) => Err(Refusal::Malformed(m.header.msg_type)),
                None => Err(Refusal::Malformed(MsgType::Cmd)),
            };
            match verdict {
                Ok(command) => {
                    let addr = client.addr(interf, index);
                    if let Err(e) = client.try_command(addr, command.body) {
                        tracing::warn!(%robot, "command from Zenoh not sent: {e}");
                    }
                }
                Err(why) => refuse(&handler, &robot, stamp.as_ref(), &why),
            }
        })
        .wait()?)
}

fn handler_verdict(
    shared: &FrontShared,
    stamp: Option<&Stamp>,
    message: &Message,
) -> Result<(), Refusal> {
    authorise(
        shared.config.controller.as_deref(),
        stamp,
        message,
        SystemTime::now(),
    )
}

fn refuse(shared: &FrontShared, robot: &RobotKey, stamp: Option<&Stamp>, why: &Refusal) {
    let refused = shared.refused.fetch_add(1, Ordering::Relaxed) + 1;
    // A refused driver sends commands at 10-20 Hz: say so on the 1st, 2nd, 4th, 8th… only.
    if refused.is_power_of_two() {
        tracing::warn!(%robot, sender = ?stamp.map(|s| &s.sender), refused, "refused from Zenoh: {why}");
    } else {
        tracing::debug!(%robot, sender = ?stamp.map(|s| &s.sender), "refused from Zenoh: {why}");
    }
}

/// The queryable taking requests for every robot of the site.
pub(crate) fn declare_requests(shared: &Arc<FrontShared>) -> Result<Queryable<()>, ZenohError> {
    let handler = shared.clone();
    Ok(shared
        .session
        .declare_queryable(every_device(&shared.config.site, Leaf::Cmd))
        .callback(move |query| on_request(&handler, query))
        .wait()?)
}

fn on_request(shared: &Arc<FrontShared>, query: Query) {
    let key = query.key_expr().as_str().to_string();
    let (Some(robot), Some((interf, index, _))) = (RobotKey::of_key(&key), device_of_key(&key))
    else {
        return;
    };
    let Some(client) = shared.client(&robot) else {
        return;
    };
    let stamp = stamp_of(query.attachment());
    let request = query.payload().and_then(|p| decode_raw(&p.to_bytes()));
    let Some(request) = request.filter(|r| r.header.msg_type == MsgType::Req) else {
        refuse(
            shared,
            &robot,
            stamp.as_ref(),
            &Refusal::Malformed(MsgType::Req),
        );
        return;
    };
    let addr = client.addr(interf, index);
    let subtype = request.header.subtype;
    let nack = Message::new(addr, MsgType::Nack, subtype, Body::Empty).to_bytes();
    if let Err(why) = handler_verdict(shared, stamp.as_ref(), &request) {
        refuse(shared, &robot, stamp.as_ref(), &why);
        reply(&query, &key, nack);
        return;
    }
    let pending = client.request_async(addr, subtype, request.body);
    // The answer takes a round trip to the robot: wait for it off Zenoh's threads.
    shared.runtime.spawn_blocking(move || {
        let answer = match pending.wait(REQUEST_WAIT) {
            Ok(ack) => ack.to_bytes(),
            Err(e) => {
                tracing::debug!(%robot, "request from Zenoh not answered: {e}");
                nack
            }
        };
        reply(&query, &key, answer);
    });
}

fn reply(query: &Query, key: &str, message: Bytes) {
    if let Err(e) = query.reply(key.to_string(), message).wait() {
        tracing::debug!(key, "reply not sent: {e}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use player_proto::interfaces::position2d::{Position2d, Position2dCmdVel};
    use player_proto::interfaces::{laser, position2d};
    use player_proto::wire::{DevAddr, Interface};

    fn addr(interf: Interface) -> DevAddr {
        DevAddr {
            host: 0,
            robot: 6665,
            interf,
            index: 0,
        }
    }

    #[test]
    fn only_the_controller_commands_and_only_fresh() {
        let command = Message::typed(
            addr(Interface::POSITION2D),
            MsgType::Cmd,
            Position2d::Velocity(Position2dCmdVel::default()),
        );
        let now = SystemTime::now();
        let teacher = Stamp::now("teacher");
        assert_eq!(
            authorise(Some("teacher"), Some(&teacher), &command, now),
            Ok(())
        );
        let pupil = Stamp::now("pupil");
        assert!(matches!(
            authorise(Some("teacher"), Some(&pupil), &command, now),
            Err(Refusal::NotController(_))
        ));
        assert!(authorise(None, Some(&teacher), &command, now).is_err());
        assert_eq!(
            authorise(Some("teacher"), None, &command, now),
            Err(Refusal::NoStamp)
        );
        let later = now + Duration::from_secs(1);
        assert!(matches!(
            authorise(Some("teacher"), Some(&teacher), &command, later),
            Err(Refusal::Stale(_))
        ));
    }

    #[test]
    fn anyone_may_read_but_only_the_controller_configure() {
        let get = Message::new(
            addr(Interface::LASER),
            MsgType::Req,
            laser::REQ_GET_GEOM,
            Body::Empty,
        );
        let set = Message::new(
            addr(Interface::POSITION2D),
            MsgType::Req,
            position2d::REQ_RESET_ODOM,
            Body::Empty,
        );
        let now = SystemTime::now();
        let pupil = Stamp::now("pupil");
        assert_eq!(authorise(Some("teacher"), Some(&pupil), &get, now), Ok(()));
        assert!(authorise(Some("teacher"), Some(&pupil), &set, now).is_err());
        let raw = get.to_bytes();
        assert_eq!(
            decode_raw(&raw).map(|m| m.header.subtype),
            Some(laser::REQ_GET_GEOM)
        );
        assert_eq!(decode_raw(&raw[..raw.len() - 1]), None);
    }
}

//! What `playerrecord record` asks each device once subscribed, so that the recording holds
//! where things are and not only what they sense: geometries (the frame tree robot → sensor
//! of an MCAP export, the robot's size), a ranger's configuration (its scan angles) and a
//! map's info. The replies are recorded like everything else, and a replay answers the same
//! questions with them.

use std::time::Duration;

use player_proto::client::{Client, PendingReply};
use player_proto::interfaces::{fiducial, laser, map, position2d, ranger, sonar};
use player_proto::message::Body;
use player_proto::wire::{DevAddr, Interface};

/// The empty-bodied requests that describe a device of this interface.
fn questions(interf: Interface) -> &'static [u8] {
    match interf {
        Interface::LASER => &[laser::REQ_GET_GEOM, laser::REQ_GET_CONFIG],
        Interface::RANGER => &[ranger::REQ_GET_GEOM, ranger::REQ_GET_CONFIG],
        Interface::SONAR => &[sonar::REQ_GET_GEOM],
        Interface::POSITION2D => &[position2d::REQ_GET_GEOM],
        Interface::FIDUCIAL => &[fiducial::REQ_GET_GEOM],
        Interface::MAP => &[map::REQ_GET_INFO],
        _ => &[],
    }
}

/// Asks every device its questions at once, then waits for the answers; a device that
/// refuses one (a NACK) or does not answer in time is only logged.
pub fn describe<'a>(devices: impl IntoIterator<Item = (&'a Client, DevAddr)>, wait: Duration) {
    let mut pending: Vec<(&Client, DevAddr, u8, PendingReply)> = Vec::new();
    for (client, addr) in devices {
        for &subtype in questions(addr.interf) {
            let reply = client.request_async(addr, subtype, Body::Empty);
            pending.push((client, addr, subtype, reply));
        }
    }
    for (client, addr, subtype, reply) in pending {
        if let Err(e) = reply.wait(wait) {
            let (host, port) = (client.host(), client.port());
            let (interf, index) = (addr.interf, addr.index);
            tracing::debug!("{host}:{port} {interf}:{index} request {subtype}: {e}");
        }
    }
}

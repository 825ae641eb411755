//! What a recorder or a relay asks each device once subscribed, so that what it passes on
//! holds where things are and not only what they sense: geometries (a robot's size, the frame
//! tree robot → sensor), a ranger's or laser's configuration (its scan angles), and a map's
//! info and then its tiles. The replies reach the client's tap like everything else; nothing
//! here keeps them.

use std::time::{Duration, Instant};

use crate::interfaces::map::Map;
use crate::interfaces::{fiducial, laser, map, position2d, ranger, sonar};
use crate::message::Body;
use crate::wire::{DevAddr, Interface};

use super::{Client, PendingReply};

/// The empty-bodied requests that describe a device of this interface.
pub fn questions(interf: Interface) -> &'static [u8] {
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

/// How much was answered.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct Described {
    pub asked: usize,
    pub answered: usize,
    pub map_tiles: usize,
}

/// Asks every device its questions at once, then waits for the answers (all within `wait`),
/// then asks each map for its tiles and waits for those; a refusal (a NACK) or a silence is
/// only logged.
pub fn describe<'a>(
    devices: impl IntoIterator<Item = (&'a Client, DevAddr)>,
    wait: Duration,
) -> Described {
    let mut described = Described::default();
    let mut pending: Vec<(&Client, DevAddr, u8, PendingReply)> = Vec::new();
    for (client, addr) in devices {
        for &subtype in questions(addr.interf) {
            let reply = client.request_async(addr, subtype, Body::Empty);
            pending.push((client, addr, subtype, reply));
        }
    }
    described.asked = pending.len();
    let deadline = Instant::now() + wait;
    let mut tiles = Vec::new();
    for (client, addr, subtype, reply) in pending {
        match reply.wait(deadline.saturating_duration_since(Instant::now())) {
            Ok(message) => {
                described.answered += 1;
                if let Ok(info) = Map::REQ_GET_INFO.reply_of(&message) {
                    for tile in info.tile_requests() {
                        let body = Map::REQ_GET_DATA.to_body(tile);
                        tiles.push((
                            client,
                            addr,
                            client.request_async(addr, map::REQ_GET_DATA, body),
                        ));
                    }
                }
            }
            Err(e) => log_unanswered(client, addr, subtype, &e),
        }
    }
    let deadline = Instant::now() + wait;
    for (client, addr, reply) in tiles {
        match reply.wait(deadline.saturating_duration_since(Instant::now())) {
            Ok(_) => described.map_tiles += 1,
            Err(e) => log_unanswered(client, addr, map::REQ_GET_DATA, &e),
        }
    }
    described
}

fn log_unanswered(client: &Client, addr: DevAddr, subtype: u8, e: &super::RequestError) {
    let (host, port) = (client.host(), client.port());
    let (interf, index) = (addr.interf, addr.index);
    tracing::debug!("{host}:{port} {interf}:{index} request {subtype}: {e}");
}

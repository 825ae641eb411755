//! A tap on a client's traffic: the robot thread hands every message it receives or sends,
//! exactly as it crossed the wire, to whoever asked (a recorder), without copying a received
//! body.

use std::sync::Arc;
use std::time::SystemTime;

use bytes::Bytes;

use crate::capture::Direction;
use crate::robot_id::RobotId;
use crate::wire::{Banner, Header};

/// What one connection's tap is told.
#[derive(Debug, Clone, Copy)]
pub enum TapEvent<'a> {
    /// A connection was established; the server's banner.
    Opened(&'a Banner),
    /// A whole message: its header and exactly `header.size` body bytes.
    Frame {
        direction: Direction,
        header: &'a Header,
        body: &'a Bytes,
    },
    /// The connection ended, and why.
    Closed(&'a str),
}

/// The tap of one robot connection, called on its robot thread with the time the message was
/// whole. Must not block: a slow tap slows the robot.
pub type ConnectionTap = Arc<dyn Fn(SystemTime, TapEvent<'_>) + Send + Sync>;

/// Called once per robot thread, with its host and port, for that connection's tap.
pub type Tap = Arc<dyn Fn(&str, u16) -> ConnectionTap + Send + Sync>;

/// Called once per robot with who it is (its name included, where it has one), for that
/// robot's connection tap: how a relay hands its robots to the fronts it feeds.
pub type RobotTap = Arc<dyn Fn(&RobotId) -> ConnectionTap + Send + Sync>;

/// A client [`Tap`] from a [`RobotTap`], for clients that know no names: each robot is
/// `host:port`.
pub fn unnamed(tap: RobotTap) -> Tap {
    Arc::new(move |host: &str, port: u16| tap(&RobotId::new(host, port)))
}

/// One tap that tells every one of `taps`, in order (a recorder and a web page, say); none
/// when there are none.
pub fn fan_out(taps: Vec<Tap>) -> Option<Tap> {
    match taps.len() {
        0 => None,
        1 => taps.into_iter().next(),
        _ => Some(Arc::new(move |host: &str, port: u16| {
            let connection: Vec<ConnectionTap> = taps.iter().map(|tap| tap(host, port)).collect();
            Arc::new(move |time, event| {
                for tap in &connection {
                    tap(time, event);
                }
            })
        })),
    }
}

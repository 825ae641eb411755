//! Everything the pages are shown, in one place: each robot's link, the newest message of
//! each kind per device (what a page that opens now is sent first), and a broadcast of every
//! new message to the open pages. Fed from the relay's upstream taps; each message is turned
//! into JSON once, whatever the number of pages.

use std::collections::{BTreeMap, HashMap};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{Instant, SystemTime};

use axum::extract::ws::Utf8Bytes;
use player_proto::RobotId;
use player_proto::capture::Direction;
use player_proto::client::{DeviceStats, RobotTap, TapEvent};
use player_proto::message::Message;
use player_proto::wire::{DevAddr, Header, Interface, MsgType};
use tokio::sync::broadcast;

use crate::page::{DeviceRow, Kind, Link, Row, ToPage};
use crate::walls::Walls;

/// Frames a page may fall behind before it is sent the newest of everything instead: about
/// a second of 16 robots' data.
const BROADCAST_DEPTH: usize = 1024;

/// The interfaces the page draws; other devices' data is only counted in the rows. A camera's
/// frames would cost every page megabytes a second for nothing drawn.
const DRAWN: &[Interface] = &[
    Interface::POSITION2D,
    Interface::LASER,
    Interface::RANGER,
    Interface::SONAR,
    Interface::FIDUCIAL,
    Interface::MAP,
    Interface::LOCALIZE,
    Interface::PLANNER,
];

/// One JSON text frame, shared by every page (a cloned frame shares its bytes).
pub type Frame = Utf8Bytes;

/// What is kept of one robot.
struct Robot {
    link: Link,
    /// The newest frame per (kind, device, subtype, tile): a page that opens now starts here.
    newest: BTreeMap<(Kind, DevAddr, u8, (u32, u32)), Frame>,
    rates: HashMap<DevAddr, Rate>,
}

/// A device's readings as the client counts them (a reading sent as several messages stamped
/// alike counts once), the count at the last status, and when the newest came.
#[derive(Default)]
struct Rate {
    stats: DeviceStats,
    at_status: u64,
    newest: Option<Instant>,
}

pub struct Hub {
    robots: Mutex<BTreeMap<String, Robot>>,
    /// The world's walls, as a frame, once known.
    world: Mutex<Option<Frame>>,
    live: broadcast::Sender<Frame>,
    status_at: Mutex<Instant>,
}

impl Default for Hub {
    fn default() -> Hub {
        Hub {
            robots: Mutex::new(BTreeMap::new()),
            world: Mutex::new(None),
            live: broadcast::channel(BROADCAST_DEPTH).0,
            status_at: Mutex::new(Instant::now()),
        }
    }
}

impl Hub {
    fn robots(&self) -> MutexGuard<'_, BTreeMap<String, Robot>> {
        // Every change is whole under the lock: a poisoned lock still guards a usable value.
        self.robots.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// A tap for the relay's robots (`RelayConfig::fronts`): each is shown as its
    /// [`RobotId`] says it (its name, else `host:port`).
    pub fn robot_tap(self: &Arc<Hub>) -> RobotTap {
        let hub = self.clone();
        Arc::new(move |robot: &RobotId| {
            let hub = hub.clone();
            let name = robot.to_string();
            hub.set_link(&name, Link::Connecting);
            Arc::new(move |_time: SystemTime, event: TapEvent<'_>| match event {
                TapEvent::Opened(_) => hub.set_link(&name, Link::Connected),
                TapEvent::Closed(why) => hub.set_link(&name, Link::Reconnecting(why.to_string())),
                TapEvent::Frame {
                    direction: Direction::ServerToClient,
                    header,
                    body,
                } => hub.server_message(&name, header, body),
                TapEvent::Frame { .. } => {}
            })
        })
    }

    /// Shows `walls` under the robots, on every page from now on (and those open).
    pub fn set_walls(&self, walls: &Walls) {
        let frame = to_json(&ToPage::World { walls });
        *self.world.lock().unwrap_or_else(|e| e.into_inner()) = Some(frame.clone());
        let _ = self.live.send(frame);
    }

    /// Every new frame, from now on.
    pub fn subscribe(&self) -> broadcast::Receiver<Frame> {
        self.live.subscribe()
    }

    /// What a page that opens now is sent first: the world's walls, every robot's link,
    /// then the newest of everything, then the rows.
    pub fn snapshot(&self) -> Vec<Frame> {
        let mut frames: Vec<Frame> = (self.world.lock().unwrap_or_else(|e| e.into_inner()))
            .iter()
            .cloned()
            .collect();
        let robots = self.robots();
        for (name, robot) in robots.iter() {
            frames.push(to_json(&ToPage::Robot {
                robot: name,
                link: &robot.link,
            }));
        }
        for robot in robots.values() {
            frames.extend(robot.newest.values().cloned());
        }
        drop(robots);
        frames.push(self.rows_frame(false));
        frames
    }

    /// The status rows as a frame; with `restart`, the rates' count starts again (the
    /// once-a-second tick does that, a snapshot does not).
    pub fn rows_frame(&self, restart: bool) -> Frame {
        let now = Instant::now();
        let mut status_at = self.status_at.lock().unwrap_or_else(|e| e.into_inner());
        let elapsed = now.duration_since(*status_at).as_secs_f64().max(1e-3);
        let mut robots = self.robots();
        let rows: Vec<Row> = robots
            .iter_mut()
            .map(|(name, robot)| Row {
                robot: name.clone(),
                link: robot.link.clone(),
                devices: robot
                    .rates
                    .iter_mut()
                    .map(|(device, rate)| {
                        let row = DeviceRow {
                            device: *device,
                            hz: (rate.stats.updates - rate.at_status) as f64 / elapsed,
                            age: rate.newest.map(|t| now.duration_since(t).as_secs_f64()),
                        };
                        if restart {
                            rate.at_status = rate.stats.updates;
                        }
                        row
                    })
                    .collect(),
            })
            .collect();
        if restart {
            *status_at = now;
        }
        to_json(&ToPage::Status { rows: &rows })
    }

    /// Sends the rows to every page (the once-a-second tick).
    pub fn broadcast_rows(&self) {
        let _ = self.live.send(self.rows_frame(true));
    }

    fn set_link(&self, name: &str, link: Link) {
        let mut robots = self.robots();
        let robot = robots.entry(name.to_string()).or_insert_with(|| Robot {
            link: Link::Connecting,
            newest: BTreeMap::new(),
            rates: HashMap::new(),
        });
        if robot.link == link && link != Link::Connecting {
            return;
        }
        robot.link = link;
        if robot.link == Link::Connected {
            // A server that comes back may be another world: describe it afresh.
            robot.newest.clear();
            robot.rates.clear();
        }
        let frame = to_json(&ToPage::Robot {
            robot: name,
            link: &robot.link,
        });
        drop(robots);
        let _ = self.live.send(frame);
    }

    fn server_message(&self, name: &str, header: &Header, body: &bytes::Bytes) {
        let kind = match header.msg_type {
            MsgType::Data => Kind::Data,
            MsgType::Ack => Kind::Reply,
            _ => return,
        };
        let device = DevAddr::local(header.addr.interf, header.addr.index);
        let mut robots = self.robots();
        let Some(robot) = robots.get_mut(name) else {
            return;
        };
        if kind == Kind::Data {
            let rate = robot.rates.entry(device).or_default();
            rate.stats.count(header.timestamp, body.len());
            rate.newest = Some(Instant::now());
        }
        drop(robots);
        if !DRAWN.contains(&device.interf) {
            return;
        }
        let message = match Message::decode(*header, body.clone()) {
            Ok(message) => message,
            Err(e) => {
                tracing::debug!("{name} {device}: not shown: {e}");
                return;
            }
        };
        let tile = match &message.body {
            player_proto::message::Body::Map(player_proto::interfaces::map::Map::Tile(t)) => {
                (t.col, t.row)
            }
            _ => (0, 0),
        };
        let frame = to_json(&ToPage::Message {
            robot: name,
            kind,
            device,
            subtype: header.subtype,
            time: header.timestamp,
            body: &message.body,
        });
        if let Some(robot) = self.robots().get_mut(name) {
            let key = (kind, device, header.subtype, tile);
            robot.newest.insert(key, frame.clone());
        }
        let _ = self.live.send(frame);
    }
}

/// A page message as JSON. Serialising player-proto's types cannot fail (no maps with
/// non-string keys, no foreign types); a failure would be a bug, logged and sent as a
/// refusal rather than a panic on the robot's thread.
pub fn to_json(message: &ToPage<'_>) -> Frame {
    match serde_json::to_string(message) {
        Ok(text) => Utf8Bytes::from(text),
        Err(e) => {
            tracing::error!("a page message did not serialise: {e}");
            Utf8Bytes::from_static(
                r#"{"type":"refused","why":"internal: a message did not serialise"}"#,
            )
        }
    }
}

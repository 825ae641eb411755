//! Everything the pages are shown, in one place: each robot's link, the newest message of
//! each kind per device (what a page that opens now is sent first), and a broadcast of every
//! new message to the open pages. Fed from the relay's upstream taps; each message is turned
//! into JSON once, whatever the number of pages. What the open pages show ([`Views`]) is what
//! the hub looks at through each robot's [`Watch`], and so what the relay subscribes to; data
//! of a device no page shows is counted in the rows and not turned into JSON.

use std::collections::{BTreeMap, HashMap};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{Instant, SystemTime};

use axum::extract::ws::Utf8Bytes;
use player_front::{Device, Look, Watch};
use player_proto::RobotId;
use player_proto::capture::Direction;
use player_proto::client::{DeviceStats, RobotTap, TapEvent};
use player_proto::interfaces::player::Player;
use player_proto::message::{Body, Message};
use player_proto::wire::{DevAddr, Header, Interface, MsgType};
use tokio::sync::broadcast;

use crate::page::{DeviceRow, Kind, Link, Row, ToPage};
use crate::views::{DRAWN, Views};
use crate::walls::Walls;

/// Frames a page may fall behind before it is sent the newest of everything instead: about
/// a second of 16 robots' data.
const BROADCAST_DEPTH: usize = 1024;

/// One JSON text frame, shared by every page (a cloned frame shares its bytes).
pub type Frame = Utf8Bytes;

/// What is kept of one robot.
struct Robot {
    link: Link,
    /// The newest frame per (kind, device, subtype, tile): a page that opens now starts here.
    newest: BTreeMap<(Kind, DevAddr, u8, (u32, u32)), Frame>,
    rates: HashMap<DevAddr, Rate>,
    /// The robot's devices, as its server's device list says.
    devices: Vec<Device>,
    /// The relay's subscriptions to this robot, where it subscribes as the pages look; `None`
    /// for a robot whose client subscribes by itself (pv3d's): everything it gets is shown.
    watch: Option<Watch>,
    /// What the open pages look at now.
    looks: HashMap<Device, Look>,
}

impl Robot {
    fn new() -> Robot {
        Robot {
            link: Link::Connecting,
            newest: BTreeMap::new(),
            rates: HashMap::new(),
            devices: Vec::new(),
            watch: None,
            looks: HashMap::new(),
        }
    }

    /// Whether the pages are sent `device`'s data.
    fn shown(&self, device: Device) -> bool {
        self.watch.is_none() || self.looks.contains_key(&device)
    }

    /// Looks at what `views` show of this robot (the `rank`-th by name), and away from the
    /// rest; a device looked away from leaves no stale data for the next page.
    fn settle(&mut self, name: &str, rank: usize, views: &Views) {
        let Some(watch) = &self.watch else {
            return;
        };
        for &device in &self.devices {
            let shown = views.shows(name, rank, device);
            if shown && !self.looks.contains_key(&device) {
                self.looks.insert(device, watch.look(device));
            } else if !shown && self.looks.remove(&device).is_some() {
                self.newest.retain(|(kind, addr, _, _), _| {
                    *kind != Kind::Data || (addr.interf, addr.index) != device
                });
            }
        }
    }
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
    /// Taken before `robots` where both are, never while `robots` is held.
    views: Mutex<Views>,
    robots: Mutex<BTreeMap<String, Robot>>,
    /// The world's walls, as a frame, once known.
    world: Mutex<Option<Frame>>,
    live: broadcast::Sender<Frame>,
    status_at: Mutex<Instant>,
}

impl Default for Hub {
    fn default() -> Hub {
        Hub {
            views: Mutex::new(Views::default()),
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

    fn views(&self) -> MutexGuard<'_, Views> {
        self.views.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Looks at what the open pages show of every robot, and away from the rest.
    fn settle(&self, views: &Views) {
        for (rank, (name, robot)) in self.robots().iter_mut().enumerate() {
            robot.settle(name, rank, views);
        }
    }

    /// The relay subscribes to `robot` as the pages look, through `watch`.
    pub fn watch(&self, robot: &RobotId, watch: Watch) {
        let views = self.views();
        self.robots()
            .entry(robot.to_string())
            .or_insert_with(Robot::new)
            .watch = Some(watch);
        self.settle(&views);
    }

    /// A page opened: it shows every robot's pose, and the first robots' sensors until it
    /// says what is in its view.
    pub fn page_opened(&self, page: u64) {
        let mut views = self.views();
        views.opened(page);
        self.settle(&views);
    }

    /// A page closed: what only it showed is let go.
    pub fn page_closed(&self, page: u64) {
        let mut views = self.views();
        views.closed(page);
        self.settle(&views);
    }

    /// The page has these robots in view: their sensors are shown to it.
    pub fn page_shows(&self, page: u64, robots: &[String]) {
        let mut views = self.views();
        if views.show(page, robots) {
            self.settle(&views);
        }
    }

    /// Devices looked at now, over every robot (for tests and benches).
    pub fn looks(&self) -> usize {
        self.robots().values().map(|r| r.looks.len()).sum()
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
                devices: {
                    // A device nobody looks at has no data, and its row says it is not shown.
                    for &(interf, index) in &robot.devices {
                        robot
                            .rates
                            .entry(DevAddr::local(interf, index))
                            .or_default();
                    }
                    let watched = robot.watch.is_some();
                    let looks = &robot.looks;
                    robot.rates.iter_mut().map(move |(device, rate)| {
                        let row = DeviceRow {
                            device: *device,
                            hz: (rate.stats.updates - rate.at_status) as f64 / elapsed,
                            age: rate.newest.map(|t| now.duration_since(t).as_secs_f64()),
                            shown: !watched || looks.contains_key(&(device.interf, device.index)),
                        };
                        if restart {
                            rate.at_status = rate.stats.updates;
                        }
                        row
                    })
                }
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
        let robot = robots.entry(name.to_string()).or_insert_with(Robot::new);
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
            // Data another front or an observer looks at is counted, not sent.
            if !robot.shown((device.interf, device.index)) {
                return;
            }
        }
        drop(robots);
        let devlist = device.interf == Interface::PLAYER && kind == Kind::Reply;
        if !DRAWN.contains(&device.interf) && !devlist {
            return;
        }
        let message = match Message::decode(*header, body.clone()) {
            Ok(message) => message,
            Err(e) => {
                tracing::debug!("{name} {device}: not shown: {e}");
                return;
            }
        };
        if let Body::Player(Player::DevList(list)) = &message.body {
            return self.devices_of(name, list.devices.iter());
        }
        if devlist {
            return;
        }
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

impl Hub {
    /// The robot's server listed its devices: the pages look at those they show.
    fn devices_of<'a>(&self, name: &str, devices: impl Iterator<Item = &'a DevAddr>) {
        let views = self.views();
        if let Some(robot) = self.robots().get_mut(name) {
            robot.devices = devices.map(|d| (d.interf, d.index)).collect();
        }
        self.settle(&views);
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

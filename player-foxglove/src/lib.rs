//! Player messages as Foxglove's well-known schemas: the one conversion an MCAP export
//! (`player-mcap`) and a live Foxglove server share. `player-proto` knows nothing of Foxglove;
//! this crate knows nothing of files or sockets.
//!
//! A [`Converter`] is fed what a Player server sent one client (data, and the replies to its
//! requests: geometries, configurations, map tiles, waypoints) and gives, per message, the
//! Foxglove messages it makes, each with its topic:
//!
//! | Player | Foxglove | Topic |
//! |---|---|---|
//! | laser scan, ranger ranges, sonar ranges | `LaserScan` | `/<robot>/<interface>/<index>/scan` |
//! | position2d state | `PoseInFrame` (world), `FrameTransform` world → robot | `…/pose`, `/<robot>/tf` |
//! | a device's geometry | `FrameTransform` robot → device | `/<robot>/tf` |
//! | localize's best hypothesis | `PoseInFrame` (world) | `…/pose` |
//! | map info and tiles | `Grid` (world), once whole | `…/grid` |
//! | camera frame | `CompressedImage` (JPEG) or `RawImage` | `…/image` |
//! | position2d geometry, fiducials seen, planner waypoints | `SceneUpdate` | `…/body`, `…/fiducials`, `…/path` |
//! | what happened to a connection | `Log` ([`log`]) | `/<robot>/log` |
//!
//! `<robot>` is the caller's name for the server (`localhost:6665`). Frames: `world`, then one
//! per position2d device (`<robot>` for index 0, `<robot>#<i>` for others: Stage serves several
//! robots on one port), then one per device (`<robot>/laser/0`), a child of the position2d
//! of the same index when there is one, else of index 0's.
//!
//! With the `live` feature, [`live::FoxgloveLive`] serves the conversion over Foxglove's
//! WebSocket protocol to Foxglove Studio and Lichtblick, fed by Player client taps.

pub mod camera;
pub mod device_topics;
pub mod frames;
#[cfg(feature = "live")]
pub mod live;
pub mod map;
pub mod message;
pub mod scans;
pub mod scene;

use std::collections::{BTreeSet, HashMap};

use bytes::Bytes;
use foxglove::messages::log::Level;
use foxglove::messages::{Log, PoseInFrame, Timestamp};
use player_proto::interfaces::common::{Pose2d, Pose3d};
use player_proto::interfaces::localize::Localize;
use player_proto::interfaces::player::Player;
use player_proto::interfaces::{
    camera::Camera, fiducial::Fiducial, laser::Laser, laser::LaserScanView, map::Map,
    planner::Planner, position2d::Position2d, ranger::Ranger, sonar::Sonar,
};
use player_proto::message::{Body, Message};
use player_proto::wire::{Header, Interface, MsgType};

pub use device_topics::device_topics;
pub use message::{FoxgloveMessage, MESSAGE_ENCODING, Output};

use frames::{WORLD, device_frame, pose2d, pose3d, timestamp, transform};
use map::MapState;
use scans::RangerState;

/// What a converter remembers of one server.
#[derive(Debug, Default)]
struct Robot {
    /// position2d indices: the robots this server serves.
    positions: BTreeSet<u16>,
    rangers: HashMap<u16, RangerState>,
    sonars: HashMap<u16, Vec<Pose3d>>,
    maps: HashMap<u16, MapState>,
}

/// Turns what Player servers sent into Foxglove messages.
#[derive(Debug, Default)]
pub struct Converter {
    robots: HashMap<String, Robot>,
}

/// The frame of the position2d device `index` of `robot`.
pub fn body_frame(robot: &str, index: u16) -> String {
    if index == 0 {
        frames::robot_frame(robot)
    } else {
        format!("{robot}#{index}")
    }
}

/// A line for a connection's log (connected, closed and why).
pub fn log(robot: &str, time: Timestamp, level: Level, text: &str) -> Output {
    Output {
        topic: format!("/{robot}/log"),
        message: FoxgloveMessage::Log(Log {
            timestamp: Some(time),
            level: level as i32,
            message: text.into(),
            name: robot.into(),
            file: String::new(),
            line: 0,
        }),
    }
}

impl Converter {
    pub fn new() -> Converter {
        Converter::default()
    }

    /// The Foxglove messages a message from the server `robot` makes (none for a message sent
    /// to a server, or one nothing here shows). A body that does not decode makes none.
    pub fn server_message(&mut self, robot: &str, header: &Header, body: &Bytes) -> Vec<Output> {
        if !matches!(header.msg_type, MsgType::Data | MsgType::Ack) {
            return Vec::new();
        }
        // Laser scans, the messages that come most often and weigh most, are read where they
        // lie: the conversion copies each range once, into the Foxglove scan, with no owned
        // scan in between.
        let scan = match Laser::DATA_SCAN.view(header, body) {
            Some(scan) => Some(scan),
            None => Laser::DATA_SCANPOSE
                .view(header, body)
                .map(|pose| pose.map(|pose| pose.scan)),
        };
        let converted = match scan {
            Some(scan) => scan.map(|scan| self.laser_scan(robot, header, &scan)),
            None => Message::decode(*header, body.clone()).map(|m| self.convert(robot, &m)),
        };
        converted.unwrap_or_else(|e| {
            tracing::debug!("{robot}: not converted: {e}");
            Vec::new()
        })
    }

    fn laser_scan(&mut self, name: &str, header: &Header, scan: &LaserScanView<'_>) -> Vec<Output> {
        let index = header.addr.index;
        let frame = device_frame(name, "laser", index);
        let time = timestamp(header.timestamp);
        vec![Output {
            topic: format!("/{name}/laser/{index}/scan"),
            message: FoxgloveMessage::LaserScan(scans::laser(time, &frame, scan)),
        }]
    }

    fn convert(&mut self, name: &str, message: &Message) -> Vec<Output> {
        let h = &message.header;
        let (interf, index) = (h.addr.interf, h.addr.index);
        let time = timestamp(h.timestamp);
        let state = self.robots.entry(name.to_string()).or_default();
        let parent = if state.positions.contains(&index) {
            body_frame(name, index)
        } else {
            body_frame(name, 0)
        };
        let kind = interf
            .name()
            .map_or_else(|| interf.0.to_string(), str::to_string);
        let frame = device_frame(name, &kind, index);
        let topic = |what: &str| format!("/{name}/{kind}/{index}/{what}");
        let tf = |pose: &Pose3d| Output {
            topic: format!("/{name}/tf"),
            message: FoxgloveMessage::FrameTransform(transform(
                time,
                &parent,
                &frame,
                pose3d(pose),
            )),
        };
        let scans = |scans: Vec<foxglove::messages::LaserScan>| -> Vec<Output> {
            scans
                .into_iter()
                .map(|s| Output {
                    topic: topic("scan"),
                    message: FoxgloveMessage::LaserScan(s),
                })
                .collect()
        };
        let out = |what: &str, message| {
            vec![Output {
                topic: topic(what),
                message,
            }]
        };
        match &message.body {
            Body::Player(Player::DevList(list)) => {
                for addr in &list.devices {
                    if addr.interf == Interface::POSITION2D {
                        state.positions.insert(addr.index);
                    }
                }
                Vec::new()
            }
            Body::Laser(Laser::Geometry(g)) => vec![tf(&g.pose)],
            Body::Ranger(Ranger::Geometry(g) | Ranger::GeometryData(g)) => {
                state.rangers.entry(index).or_default().geometry = Some(g.clone());
                vec![tf(&g.pose)]
            }
            Body::Ranger(Ranger::Config(c)) => {
                state.rangers.entry(index).or_default().config = Some(*c);
                Vec::new()
            }
            Body::Ranger(Ranger::Ranges(r)) => {
                let ranger = state.rangers.entry(index).or_default();
                scans(scans::ranger(time, &frame, ranger, &r.ranges))
            }
            Body::Ranger(Ranger::RangesStamped(r)) => {
                let ranger = state.rangers.entry(index).or_default();
                if r.have_geom != 0 {
                    ranger.geometry = Some(r.geom.clone());
                }
                if r.have_config != 0 {
                    ranger.config = Some(r.config);
                }
                scans(scans::ranger(time, &frame, ranger, &r.data.ranges))
            }
            Body::Sonar(Sonar::Geometry(g) | Sonar::GeometryData(g)) => {
                state.sonars.insert(index, g.poses.clone());
                vec![tf(&Pose3d::default())]
            }
            Body::Sonar(Sonar::Ranges(d)) => match state.sonars.get(&index) {
                Some(poses) => scans(scans::sonar(time, &frame, poses, &d.ranges)),
                None => Vec::new(),
            },
            Body::Position2d(Position2d::State(d)) => {
                state.positions.insert(index);
                let body = body_frame(name, index);
                vec![
                    Output {
                        topic: format!("/{name}/tf"),
                        message: FoxgloveMessage::FrameTransform(transform(
                            time,
                            WORLD,
                            &body,
                            pose2d(&d.pos),
                        )),
                    },
                    pose_in_world(topic("pose"), time, &d.pos),
                ]
            }
            Body::Position2d(Position2d::Geometry(g) | Position2d::GeometryData(g)) => {
                let body = body_frame(name, index);
                let update = scene::body(time, &body, &g.pose, &g.size);
                out("body", FoxgloveMessage::SceneUpdate(update))
            }
            Body::Localize(Localize::Hypotheses(d)) => {
                let best = d.hypoths.iter().max_by(|a, b| a.alpha.total_cmp(&b.alpha));
                best.map_or_else(Vec::new, |h| {
                    vec![pose_in_world(topic("pose"), time, &h.mean)]
                })
            }
            Body::Camera(Camera::State(c) | Camera::Image(c)) => {
                match camera::image(time, &frame, c) {
                    Ok(image) => out("image", image),
                    Err(e) => {
                        tracing::debug!("{name} {kind}:{index}: frame not converted: {e}");
                        Vec::new()
                    }
                }
            }
            Body::Map(Map::Info(info) | Map::InfoData(info)) => {
                let known = state.maps.get(&index).map(MapState::info);
                if known != Some(info) {
                    match MapState::new(*info) {
                        Ok(map) => {
                            state.maps.insert(index, map);
                        }
                        Err(e) => tracing::debug!("{name} {kind}:{index}: {e}"),
                    }
                }
                Vec::new()
            }
            Body::Map(Map::Tile(tile)) => {
                let Some(map) = state.maps.get_mut(&index) else {
                    return Vec::new();
                };
                match map.tile(time, tile) {
                    Ok(Some(grid)) => out("grid", FoxgloveMessage::Grid(grid)),
                    Ok(None) => Vec::new(),
                    Err(e) => {
                        tracing::debug!("{name} {kind}:{index}: tile not converted: {e}");
                        Vec::new()
                    }
                }
            }
            Body::Fiducial(Fiducial::Geometry(g)) => vec![tf(&g.pose)],
            Body::Fiducial(Fiducial::Scan(d)) => {
                let update = scene::fiducials(time, &frame, &d.fiducials);
                out("fiducials", FoxgloveMessage::SceneUpdate(update))
            }
            Body::Planner(Planner::Waypoints(w)) => {
                let update = scene::path(time, &topic("path"), &w.waypoints);
                out("path", FoxgloveMessage::SceneUpdate(update))
            }
            _ => Vec::new(),
        }
    }
}

fn pose_in_world(topic: String, time: Timestamp, pose: &Pose2d) -> Output {
    Output {
        topic,
        message: FoxgloveMessage::PoseInFrame(PoseInFrame {
            timestamp: Some(time),
            frame_id: WORLD.into(),
            pose: Some(pose2d(pose)),
        }),
    }
}

#[cfg(test)]
mod tests;

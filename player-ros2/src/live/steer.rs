//! Steering a Player robot from ROS 2, as the bridge and the relay's front both do: once it is
//! there, its map on `/map` and its sensors' fixed transforms on `/tf_static` (kept for late
//! subscribers); then, over and over, its `cmd_vel` to its base (checked, with a deadline),
//! goals to its planner and starts to its localizer.

use std::collections::HashSet;
use std::time::Instant;

use super::RobotNode;
use super::commands::{Deadline, Refused, goal, initial_pose, velocity};
use crate::map::grid;
use crate::msgs::{Header, Quaternion, TFMessage, Time, Transform, TransformStamped, Vector3};
use crate::names::frame;
use player_proto::RobotId;
use player_proto::client::Client;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::laser::Laser;
use player_proto::interfaces::localize::{Localize, LocalizeSetPose};
use player_proto::interfaces::map::Map;
use player_proto::interfaces::planner::{Planner, PlannerCmd};
use player_proto::wire::Interface;

/// Publishes the robot's map(s) and its lasers' places on its base.
pub fn latched(robot: &RobotId, client: &Client, node: &mut RobotNode) {
    let ns = node.namespace().to_string();
    let mut transforms = Vec::new();
    for device in client.devices() {
        let addr = device.addr;
        if addr.interf == Interface::LASER {
            match client.fetch(addr, Laser::REQ_GET_GEOM) {
                Ok(geometry) => transforms.push(TransformStamped {
                    header: Header::new(Time::default(), frame(&ns, "base_link", 0)),
                    child_frame_id: frame(&ns, "laser", addr.index),
                    transform: Transform {
                        translation: Vector3 {
                            x: geometry.pose.px,
                            y: geometry.pose.py,
                            z: geometry.pose.pz,
                        },
                        rotation: Quaternion::yaw(geometry.pose.pyaw),
                    },
                }),
                Err(e) => tracing::warn!("{robot}: no geometry for {addr}: {e}"),
            }
        }
        if addr.interf == Interface::MAP {
            let topic = if addr.index == 0 {
                "/map".to_string()
            } else {
                format!("/map_{}", addr.index)
            };
            match fetch_map(client, addr) {
                Ok(map) => {
                    let (w, h) = (map.info.width, map.info.height);
                    match node.publish_map(&topic, map) {
                        Ok(()) => tracing::info!("{robot}: its map ({w} x {h} cells) on {topic}"),
                        Err(e) => tracing::warn!("{robot}: {e}"),
                    }
                }
                Err(e) => tracing::warn!("{robot}: cannot read the map {addr}: {e}"),
            }
        }
    }
    if !transforms.is_empty()
        && let Err(e) = node.publish_static(TFMessage { transforms })
    {
        tracing::warn!("{robot}: {e}");
    }
}

/// The whole grid of a map device, tile by tile.
fn fetch_map(
    client: &Client,
    addr: player_proto::wire::DevAddr,
) -> Result<crate::msgs::OccupancyGrid, MapReadError> {
    let info = client.fetch(addr, Map::REQ_GET_INFO)?;
    let mut tiles = Vec::new();
    for ask in info.tile_requests() {
        let reply = client.request_with(addr, Map::REQ_GET_DATA, ask)?;
        tiles.push(Map::REQ_GET_DATA.reply_of(&reply)?);
    }
    Ok(grid(&info, &tiles, Header::new(Time::default(), "map"))?)
}

/// Why a robot's map could not be read.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum MapReadError {
    #[error(transparent)]
    Request(#[from] player_proto::client::RequestError),
    #[error("a bad tile: {0}")]
    Tile(#[from] player_proto::interfaces::map::MapError),
}

/// Goals to the robot's planner, starts to its localizer; what is unsound, refused (said once
/// per kind).
fn goals_and_poses(
    robot: &RobotId,
    client: &Client,
    node: &RobotNode,
    refused: &mut HashSet<&'static str>,
) {
    let mut refuse = |kind: &'static str, why: &dyn std::fmt::Display| {
        if refused.insert(kind) {
            tracing::warn!("{robot}: refused {why} (said once)");
        }
    };
    for asked in node.goals() {
        match goal(&asked) {
            Ok((x, y, a)) => {
                tracing::info!("{robot}: goal ({x:.2}, {y:.2}, {a:.2}) to its planner");
                let addr = client.addr(Interface::PLANNER, 0);
                client.command(
                    addr,
                    Planner::Goal(PlannerCmd {
                        goal: Pose2d::new(x, y, a),
                    }),
                );
            }
            Err(why) => refuse("goal", &why),
        }
    }
    for asked in node.initial_poses() {
        match initial_pose(&asked) {
            Ok(((x, y, a), cov)) => {
                let addr = client.addr(Interface::LOCALIZE, 0);
                let start = LocalizeSetPose {
                    mean: Pose2d::new(x, y, a),
                    cov,
                };
                if let Err(e) = client.request_with(addr, Localize::REQ_SET_POSE, start) {
                    tracing::warn!("{robot}: the localizer refused the initial pose: {e}");
                }
            }
            Err(why) => refuse("initial pose", &why),
        }
    }
}

/// What steering one robot remembers: when its base must be stopped, what was refused.
#[derive(Debug)]
pub struct Steering {
    robot: RobotId,
    deadline: Deadline,
    /// Kinds of refused command already said.
    refused: HashSet<&'static str>,
}

impl Steering {
    pub fn new(robot: &RobotId) -> Steering {
        Steering {
            robot: robot.clone(),
            deadline: Deadline::default(),
            refused: HashSet::new(),
        }
    }

    /// What ROS 2 told the robot since the last call, passed on: goals and starts, then the
    /// newest sound `cmd_vel` (each unsound one refused), and a stop when they stopped coming.
    pub fn steer(&mut self, node: &RobotNode, client: &Client) {
        goals_and_poses(&self.robot, client, node, &mut self.refused);
        let now = Instant::now();
        let base = client.position2d(0);
        let mut newest = None;
        for twist in node.cmd_vels() {
            match velocity(&twist) {
                Ok(v) => newest = Some(v),
                Err(refused) => {
                    let kind = match refused {
                        Refused::NotFinite(_) => "not finite",
                        _ => "absurd",
                    };
                    if self.refused.insert(kind) {
                        tracing::warn!("{}: refused {refused} (said once)", self.robot);
                    }
                }
            }
        }
        if let Some((vx, vy, va)) = newest {
            base.set_velocity(vx, vy, va);
            self.deadline.commanded((vx, vy, va), now);
        }
        if self.deadline.expired(now) {
            tracing::info!("{}: no cmd_vel for half a second: stopping", self.robot);
            base.set_velocity(0.0, 0.0, 0.0);
        }
    }
}

//! What a robot says of itself once it is there, asked of it without holding its node (a
//! reply may pass through the relay's tap, which publishes through that same node): its
//! lasers' places on its base for `/tf_static`, its sonars' and rangers' geometries and
//! configurations for placing their echoes, and its map(s) for `/map`; then given to its node.

use player_proto::RobotId;
use player_proto::client::Client;
use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::laser::Laser;
use player_proto::interfaces::map::Map;
use player_proto::interfaces::ranger::{Ranger, RangerConfig, RangerGeometry};
use player_proto::interfaces::sonar::Sonar;
use player_proto::wire::{DevAddr, Interface};

use super::RobotNode;
use crate::convert::map_topic;
use crate::map::grid;
use crate::msgs::{
    Header, OccupancyGrid, Quaternion, TFMessage, Time, Transform, TransformStamped, Vector3,
};
use crate::names::frame;

/// What the robot said of itself.
#[derive(Debug, Default)]
pub struct Described {
    /// position2d indices: the robots' bases on this port.
    bases: Vec<u16>,
    lasers: Vec<(u16, Pose3d)>,
    sonars: Vec<(u16, Vec<Pose3d>)>,
    ranger_geometries: Vec<(u16, RangerGeometry)>,
    ranger_configs: Vec<(u16, RangerConfig)>,
    maps: Vec<(String, OccupancyGrid)>,
}

/// Asks `client`'s robot what describes its devices; what it cannot answer is said and left.
pub fn describe(robot: &RobotId, client: &Client) -> Described {
    let mut said = Described::default();
    let missing = |addr: DevAddr, what: &str, e: &dyn std::fmt::Display| {
        tracing::warn!("{robot}: no {what} for {addr}: {e}");
    };
    for device in client.devices() {
        let addr = device.addr;
        let index = addr.index;
        match addr.interf {
            Interface::POSITION2D => said.bases.push(index),
            Interface::LASER => match client.fetch(addr, Laser::REQ_GET_GEOM) {
                Ok(g) => said.lasers.push((index, g.pose)),
                Err(e) => missing(addr, "geometry", &e),
            },
            Interface::SONAR => match client.fetch(addr, Sonar::REQ_GET_GEOM) {
                Ok(g) => said.sonars.push((index, g.poses)),
                Err(e) => missing(addr, "geometry", &e),
            },
            Interface::RANGER => {
                match client.fetch(addr, Ranger::REQ_GET_GEOM) {
                    Ok(g) => said.ranger_geometries.push((index, g)),
                    Err(e) => missing(addr, "geometry", &e),
                }
                match client.fetch(addr, Ranger::REQ_GET_CONFIG) {
                    Ok(c) => said.ranger_configs.push((index, c)),
                    Err(e) => missing(addr, "configuration", &e),
                }
            }
            Interface::MAP => match fetch_map(client, addr) {
                Ok(map) => said.maps.push((map_topic(index), map)),
                Err(e) => tracing::warn!("{robot}: cannot read the map {addr}: {e}"),
            },
            _ => {}
        }
    }
    said
}

impl Described {
    /// Gives `node` what the robot said: geometries to its conversion, its lasers' places on
    /// `/tf_static`, its maps on `/map`.
    pub fn publish(self, robot: &RobotId, node: &mut RobotNode) {
        for index in &self.bases {
            node.converter().base(*index);
        }
        for (index, poses) in &self.sonars {
            node.converter().sonar_geometry(*index, poses);
        }
        for (index, geometry) in &self.ranger_geometries {
            node.converter().ranger_geometry(*index, geometry);
        }
        for (index, config) in &self.ranger_configs {
            node.converter().ranger_config(*index, config);
        }
        for (topic, map) in self.maps {
            let (w, h) = (map.info.width, map.info.height);
            match node.publish_map(&topic, map) {
                Ok(()) => tracing::info!("{robot}: its map ({w} x {h} cells) on {topic}"),
                Err(e) => tracing::warn!("{robot}: {e}"),
            }
        }
        let converter = node.converter().clone();
        let transforms: Vec<_> = self
            .lasers
            .iter()
            .map(|(index, pose)| TransformStamped {
                header: Header::new(Time::default(), converter.base_frame(*index)),
                child_frame_id: frame(converter.namespace(), "laser", *index),
                transform: Transform {
                    translation: Vector3 {
                        x: pose.px,
                        y: pose.py,
                        z: pose.pz,
                    },
                    rotation: Quaternion::yaw(pose.pyaw),
                },
            })
            .collect();
        if !transforms.is_empty()
            && let Err(e) = node.publish_static(TFMessage { transforms })
        {
            tracing::warn!("{robot}: {e}");
        }
    }
}

/// The whole grid of a map device, tile by tile.
fn fetch_map(client: &Client, addr: DevAddr) -> Result<OccupancyGrid, MapReadError> {
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

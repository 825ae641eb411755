//! One robot's conversion: Player's messages as ROS 2's ([`crate::convert`]), and what the
//! robot's devices said of themselves before — sonar and ranger geometries, ranger
//! configurations (in replies, or in data), a map's info and its tiles one reply at a time —
//! remembered, so that echoes can be placed and a map put together when it is whole.

use std::collections::{BTreeSet, HashMap};

use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::map::Map;
use player_proto::interfaces::player::Player;
use player_proto::interfaces::ranger::{Ranger, RangerConfig, RangerGeometry};
use player_proto::interfaces::sonar::Sonar;
use player_proto::message::{Body, Message};
use player_proto::wire::{Interface, MsgType};

use crate::convert::{MAP_FRAME, convert, map_topic};
use crate::map::MapTiles;
use crate::msgs::{Header, Time};
use crate::names::{frame, topic};
use crate::out::{Converted, RosOut};
use crate::ranges::RangerState;

/// The conversion of one robot's messages: its namespace, and what its devices told of
/// themselves (sonar and ranger geometries, ranger configurations, a map's info and tiles).
#[derive(Debug, Clone, Default)]
pub struct Converter {
    ns: String,
    sonars: HashMap<u16, Vec<Pose3d>>,
    rangers: HashMap<u16, RangerState>,
    maps: HashMap<u16, MapTiles>,
    /// The robot's bases (position2d indices): several robots on one port number their devices
    /// alike, and a device of index `i` belongs to base `i` where there is one (pv3d binds them
    /// so); where there is none (one robot's second ranger) it is base 0's.
    bases: BTreeSet<u16>,
}

impl Converter {
    /// The conversion of the robot of namespace `ns`.
    pub fn new(ns: impl Into<String>) -> Converter {
        Converter {
            ns: ns.into(),
            ..Converter::default()
        }
    }

    pub fn namespace(&self) -> &str {
        &self.ns
    }

    /// position2d `index` is one of the robot's bases.
    pub fn base(&mut self, index: u16) {
        self.bases.insert(index);
    }

    /// The frame a device of `index` is placed in: its base's.
    pub fn base_frame(&self, index: u16) -> String {
        let base = if self.bases.contains(&index) {
            index
        } else {
            0
        };
        frame(&self.ns, "base_link", base)
    }

    /// Sonar `index`'s transducers, on the robot.
    pub fn sonar_geometry(&mut self, index: u16, poses: &[Pose3d]) {
        self.sonars.insert(index, poses.to_vec());
    }

    /// Ranger `index`'s place on the robot and its elements' on it.
    pub fn ranger_geometry(&mut self, index: u16, geometry: &RangerGeometry) {
        self.rangers.entry(index).or_default().geometry = Some(geometry.clone());
    }

    /// Ranger `index`'s angles and ranges.
    pub fn ranger_config(&mut self, index: u16, config: &RangerConfig) {
        self.rangers.entry(index).or_default().config = Some(*config);
    }

    /// The ROS 2 messages of `message`: none for what is not mapped, or not yet placeable.
    pub fn convert(&mut self, message: &Message) -> Vec<Converted> {
        let header = &message.header;
        let index = header.addr.index;
        let stamp = Time::from_seconds(header.timestamp);
        if header.addr.interf == Interface::POSITION2D {
            self.base(index);
        }
        match (&message.body, header.msg_type) {
            (Body::Player(Player::DevList(list)), MsgType::Ack) => {
                for addr in &list.devices {
                    if addr.interf == Interface::POSITION2D {
                        self.base(addr.index);
                    }
                }
                Vec::new()
            }
            (Body::Sonar(Sonar::Geometry(g) | Sonar::GeometryData(g)), _) => {
                self.sonar_geometry(index, &g.poses);
                Vec::new()
            }
            (Body::Sonar(Sonar::Ranges(data)), MsgType::Data) => {
                let poses = self.sonars.get(&index).map_or(&[][..], |p| &p[..]);
                let at = Header::new(stamp, self.base_frame(index));
                crate::ranges::sonar(at, poses, &data.ranges)
                    .map(|cloud| {
                        let topic = topic(&self.ns, "sonar", index);
                        vec![Converted::new(topic, stamp, RosOut::PointCloud2(cloud))]
                    })
                    .unwrap_or_default()
            }
            (Body::Ranger(Ranger::Geometry(g) | Ranger::GeometryData(g)), _) => {
                self.ranger_geometry(index, g);
                Vec::new()
            }
            (Body::Ranger(Ranger::Config(c) | Ranger::SetConfig(c)), MsgType::Ack) => {
                self.ranger_config(index, c);
                Vec::new()
            }
            (Body::Ranger(Ranger::RangesStamped(stamped)), MsgType::Data) => {
                if stamped.have_geom != 0 {
                    self.ranger_geometry(index, &stamped.geom);
                }
                if stamped.have_config != 0 {
                    self.ranger_config(index, &stamped.config);
                }
                self.ranger_ranges(index, stamp, &stamped.data.ranges)
            }
            (Body::Ranger(Ranger::Ranges(data)), MsgType::Data) => {
                self.ranger_ranges(index, stamp, &data.ranges)
            }
            (Body::Map(Map::Info(info) | Map::InfoData(info)), _) => {
                self.maps.entry(index).or_default().info(info);
                Vec::new()
            }
            (Body::Map(Map::Tile(tile)), MsgType::Ack) => {
                let header = Header::new(stamp, MAP_FRAME);
                match self.maps.entry(index).or_default().tile(tile, header) {
                    Some(grid) => vec![Converted::new(
                        map_topic(index),
                        stamp,
                        RosOut::OccupancyGrid(grid),
                    )],
                    None => Vec::new(),
                }
            }
            _ => convert(&self.ns, message),
        }
    }

    fn ranger_ranges(&self, index: u16, stamp: Time, ranges: &[f64]) -> Vec<Converted> {
        let state = self.rangers.get(&index).cloned().unwrap_or_default();
        let at = Header::new(stamp, self.base_frame(index));
        match crate::ranges::ranger(at, &state, ranges) {
            Some(cloud) => vec![Converted::new(
                topic(&self.ns, "range", index),
                stamp,
                RosOut::PointCloud2(cloud),
            )],
            None => Vec::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use player_proto::interfaces::map::{MapData, MapInfo};
    use player_proto::interfaces::sonar::{SonarData, SonarGeometry};
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
    fn echoes_come_out_once_their_geometry_came() {
        let mut r0 = Converter::new("r0");
        let ranges = Message::new(
            addr(Interface::SONAR),
            MsgType::Data,
            1,
            Body::Sonar(Sonar::Ranges(SonarData {
                ranges: vec![1.0, 2.0],
            })),
        )
        .at(3.5);
        assert!(
            r0.convert(&ranges).is_empty(),
            "where the transducers are is not known"
        );
        let pose = |yaw| Pose3d {
            pyaw: yaw,
            ..Pose3d::default()
        };
        let geometry = Message::new(
            addr(Interface::SONAR),
            MsgType::Ack,
            1,
            Body::Sonar(Sonar::Geometry(SonarGeometry {
                poses: vec![pose(0.0), pose(1.0)],
            })),
        );
        assert!(r0.convert(&geometry).is_empty());
        let out = r0.convert(&ranges);
        assert_eq!(out.len(), 1);
        assert_eq!((out[0].topic.as_str(), out[0].stamp.sec), ("/r0/sonar", 3));
        let RosOut::PointCloud2(cloud) = &out[0].message else {
            panic!("a cloud");
        };
        assert_eq!(
            (cloud.width, cloud.header.frame_id.as_str()),
            (2, "r0/base_link")
        );
        // Sonar 1: one robot's second sonar while the port has one base, the second robot's
        // once it has position2d:1.
        let on_second = |m: &Message| {
            let mut m = m.clone();
            m.header.addr.index = 1;
            m
        };
        assert!(r0.convert(&on_second(&geometry)).is_empty());
        let frame_of = |r0: &mut Converter| {
            let out = r0.convert(&on_second(&ranges));
            assert_eq!(out[0].topic, "/r0/sonar_1");
            let RosOut::PointCloud2(cloud) = &out[0].message else {
                panic!("a cloud");
            };
            cloud.header.frame_id.clone()
        };
        assert_eq!(frame_of(&mut r0), "r0/base_link");
        // The server's device list names position2d:1 (a recording has it before any data).
        let devices = player_proto::interfaces::player::DevList {
            devices: vec![addr(Interface::POSITION2D), {
                let mut second = addr(Interface::POSITION2D);
                second.index = 1;
                second
            }],
        };
        let list = Message::new(
            addr(Interface::PLAYER),
            MsgType::Ack,
            player_proto::interfaces::player::REQ_DEVLIST,
            Body::Player(Player::DevList(devices)),
        );
        assert!(r0.convert(&list).is_empty());
        assert_eq!(frame_of(&mut r0), "r0/base_link_1");
    }

    #[test]
    fn a_map_read_tile_by_tile_comes_out_whole_on_map() {
        let mut r0 = Converter::new("r0");
        let info = MapInfo {
            scale: 0.1,
            width: 2,
            height: 1,
            ..MapInfo::default()
        };
        let info = Message::new(
            addr(Interface::MAP),
            MsgType::Ack,
            1,
            Body::Map(Map::Info(info)),
        );
        assert!(r0.convert(&info).is_empty());
        let tile = MapData::compress(0, 0, 2, 1, 1, &[1, -1]);
        let tile = Message::new(
            addr(Interface::MAP),
            MsgType::Ack,
            2,
            Body::Map(Map::Tile(tile)),
        );
        let out = r0.convert(&tile);
        assert_eq!(out.len(), 1);
        let RosOut::OccupancyGrid(grid) = &out[0].message else {
            panic!("a grid");
        };
        assert_eq!(
            (out[0].topic.as_str(), grid.data.as_slice()),
            ("/map", &[100, 0][..])
        );
    }
}

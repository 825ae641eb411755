//! Player's messages as ROS 2 messages: one conversion for files and (next) the live front.
//! Units are already REP-103's (metres, radians, counter-clockwise); frames are REP-105's,
//! per robot: a base's odometry is `ns/odom` -> `ns/base_link`, a laser's scan is in
//! `ns/laser`, a localizer's estimate and a planner's path in `map`.
//!
//! Mapped: laser scans, position2d (odometry and its transform), localize (the best
//! hypothesis, with its covariance), planner way-points (the reply to a way-point request),
//! power, cameras (raw as `Image` on `/ns/image_raw`, JPEG as `CompressedImage` on
//! `/ns/image_raw/compressed`). Not yet: ranger and sonar arrays, maps (their tiles).

use player_proto::interfaces::camera::Camera;
use player_proto::interfaces::laser::{Laser, LaserScan as PlayerScan};
use player_proto::interfaces::localize::{Localize, covariance_matrix};
use player_proto::interfaces::planner::Planner;
use player_proto::interfaces::position2d::Position2d;
use player_proto::interfaces::power::Power;
use player_proto::message::{Body, Message};
use player_proto::wire::{Interface, MsgType};

use crate::cdr::{CdrError, serialize};
use crate::msgs::{
    BatteryState, CompressedImage, Header, Image, LaserScan, Odometry, Path, Pose, PoseStamped,
    PoseWithCovariance, PoseWithCovarianceStamped, RosMessage, TFMessage, Time, Transform,
    TransformStamped, Twist, TwistWithCovariance, Vector3, covariance, schema_text,
};
use crate::names::{frame, topic};

/// The interfaces whose messages [`convert`] maps: a message of any other becomes nothing, so
/// it need not even be decoded.
pub const MAPPED: [Interface; 6] = [
    Interface::LASER,
    Interface::POSITION2D,
    Interface::LOCALIZE,
    Interface::PLANNER,
    Interface::POWER,
    Interface::CAMERA,
];

/// The frame localizers and planners speak in.
pub const MAP_FRAME: &str = "map";

/// A ROS 2 message of one of the types Player's data becomes. Short-lived (made, then sent
/// or written at once), so the sizes of its variants do not matter.
#[derive(Debug, Clone, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum RosOut {
    LaserScan(LaserScan),
    Odometry(Odometry),
    Tf(TFMessage),
    PoseWithCovarianceStamped(PoseWithCovarianceStamped),
    Path(Path),
    BatteryState(BatteryState),
    Image(Image),
    CompressedImage(CompressedImage),
}

macro_rules! each_type {
    ($self:expr, $m:ident => $e:expr) => {
        match $self {
            RosOut::LaserScan($m) => $e,
            RosOut::Odometry($m) => $e,
            RosOut::Tf($m) => $e,
            RosOut::PoseWithCovarianceStamped($m) => $e,
            RosOut::Path($m) => $e,
            RosOut::BatteryState($m) => $e,
            RosOut::Image($m) => $e,
            RosOut::CompressedImage($m) => $e,
        }
    };
}

fn type_of<T: RosMessage>(_: &T) -> &'static str {
    T::TYPE
}

fn schema_of<T: RosMessage>(_: &T) -> String {
    schema_text::<T>()
}

impl RosOut {
    /// `pkg/msg/Type`.
    pub fn type_name(&self) -> &'static str {
        each_type!(self, m => type_of(m))
    }

    /// The type's schema (`ros2msg`).
    pub fn schema(&self) -> String {
        each_type!(self, m => schema_of(m))
    }

    /// The message as ROS 2 serializes it.
    pub fn cdr(&self) -> Result<Vec<u8>, CdrError> {
        each_type!(self, m => serialize(m))
    }
}

/// One ROS 2 message made from a Player message: its topic, its time and itself.
#[derive(Debug, Clone, PartialEq)]
pub struct Converted {
    pub topic: String,
    pub stamp: Time,
    pub message: RosOut,
}

fn converted(topic: String, stamp: Time, message: RosOut) -> Converted {
    Converted {
        topic,
        stamp,
        message,
    }
}

/// The ROS 2 messages of `message`, from robot namespace `ns`: none for what is not mapped.
pub fn convert(ns: &str, message: &Message) -> Vec<Converted> {
    let header = &message.header;
    let index = header.addr.index;
    let stamp = Time::from_seconds(header.timestamp);
    match (&message.body, header.msg_type) {
        (Body::Laser(Laser::Scan(scan)), MsgType::Data) => {
            let scan = laser_scan(scan, Header::new(stamp, frame(ns, "laser", index)));
            vec![converted(
                topic(ns, "scan", index),
                stamp,
                RosOut::LaserScan(scan),
            )]
        }
        (Body::Laser(Laser::ScanPose(scan)), MsgType::Data) => {
            let scan = laser_scan(&scan.scan, Header::new(stamp, frame(ns, "laser", index)));
            vec![converted(
                topic(ns, "scan", index),
                stamp,
                RosOut::LaserScan(scan),
            )]
        }
        (Body::Position2d(Position2d::State(state)), MsgType::Data) => {
            let (odom, base) = (frame(ns, "odom", index), frame(ns, "base_link", index));
            let pose = Pose::planar(state.pos.px, state.pos.py, state.pos.pa);
            let odometry = Odometry {
                header: Header::new(stamp, odom.clone()),
                child_frame_id: base.clone(),
                pose: PoseWithCovariance {
                    pose,
                    covariance: covariance([0.0; 6]),
                },
                twist: TwistWithCovariance {
                    twist: Twist {
                        linear: Vector3 {
                            x: state.vel.px,
                            y: state.vel.py,
                            z: 0.0,
                        },
                        angular: Vector3 {
                            x: 0.0,
                            y: 0.0,
                            z: state.vel.pa,
                        },
                    },
                    covariance: covariance([0.0; 6]),
                },
            };
            let tf = TFMessage {
                transforms: vec![TransformStamped {
                    header: Header::new(stamp, odom),
                    child_frame_id: base,
                    transform: Transform {
                        translation: Vector3 {
                            x: state.pos.px,
                            y: state.pos.py,
                            z: 0.0,
                        },
                        rotation: pose.orientation,
                    },
                }],
            };
            vec![
                converted(topic(ns, "odom", index), stamp, RosOut::Odometry(odometry)),
                converted("/tf".into(), stamp, RosOut::Tf(tf)),
            ]
        }
        (Body::Localize(Localize::Hypotheses(data)), MsgType::Data) => {
            let best = data
                .hypoths
                .iter()
                .max_by(|a, b| a.alpha.total_cmp(&b.alpha));
            match best {
                Some(h) => {
                    let m = covariance_matrix(&h.cov);
                    // x, y, z, roll, pitch, yaw: the plane's three, where ROS puts them.
                    let mut rows = covariance([0.0; 6]);
                    for (i, r) in [0usize, 1, 5].into_iter().enumerate() {
                        for (j, c) in [0usize, 1, 5].into_iter().enumerate() {
                            rows[r][c] = m[i][j];
                        }
                    }
                    let estimate = PoseWithCovarianceStamped {
                        header: Header::new(stamp, MAP_FRAME),
                        pose: PoseWithCovariance {
                            pose: Pose::planar(h.mean.px, h.mean.py, h.mean.pa),
                            covariance: rows,
                        },
                    };
                    let name = if index == 0 {
                        "amcl_pose".to_string()
                    } else {
                        format!("amcl_pose_{index}")
                    };
                    vec![converted(
                        format!("/{ns}/{name}"),
                        stamp,
                        RosOut::PoseWithCovarianceStamped(estimate),
                    )]
                }
                None => Vec::new(),
            }
        }
        (Body::Planner(Planner::Waypoints(w)), MsgType::Ack) => {
            let header = Header::new(stamp, MAP_FRAME);
            let path = Path {
                header: header.clone(),
                poses: w
                    .waypoints
                    .iter()
                    .map(|p| PoseStamped {
                        header: header.clone(),
                        pose: Pose::planar(p.px, p.py, p.pa),
                    })
                    .collect(),
            };
            vec![converted(
                topic(ns, "plan", index),
                stamp,
                RosOut::Path(path),
            )]
        }
        (Body::Power(Power::State(p)), MsgType::Data) => {
            let battery = BatteryState {
                header: Header::new(stamp, frame(ns, "base_link", 0)),
                voltage: p.volts,
                temperature: f32::NAN,
                current: f32::NAN,
                charge: f32::NAN,
                capacity: f32::NAN,
                design_capacity: f32::NAN,
                percentage: p.percent / 100.0,
                power_supply_status: match p.charging {
                    1 => crate::msgs::POWER_SUPPLY_STATUS_CHARGING,
                    _ => crate::msgs::POWER_SUPPLY_STATUS_DISCHARGING,
                },
                present: true,
                ..BatteryState::default()
            };
            vec![converted(
                topic(ns, "battery", index),
                stamp,
                RosOut::BatteryState(battery),
            )]
        }
        (Body::Camera(Camera::State(picture)), MsgType::Data) => {
            let header = Header::new(stamp, frame(ns, "camera", index));
            match crate::camera::picture(picture, header) {
                Some(RosOut::CompressedImage(jpeg)) => vec![converted(
                    format!("{}/compressed", topic(ns, "image_raw", index)),
                    stamp,
                    RosOut::CompressedImage(jpeg),
                )],
                Some(image) => vec![converted(topic(ns, "image_raw", index), stamp, image)],
                None => Vec::new(),
            }
        }
        _ => Vec::new(),
    }
}

/// A Player scan as ROS's: the same angles and ranges (a beam's bearing is `angle_min + i ×
/// angle_increment`, as every Player client computes it from `min_angle` and `resolution`);
/// intensities as numbers.
fn laser_scan(scan: &PlayerScan, header: Header) -> LaserScan {
    LaserScan {
        header,
        angle_min: scan.min_angle,
        angle_max: scan.max_angle,
        angle_increment: scan.resolution,
        time_increment: 0.0,
        scan_time: 0.0,
        range_min: 0.0,
        range_max: scan.max_range,
        ranges: scan.ranges.clone(),
        intensities: scan.intensity.iter().map(|&i| f32::from(i)).collect(),
    }
}

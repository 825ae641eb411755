//! nav_msgs: odometry, maps and paths.

use serde::{Deserialize, Serialize};

use super::RosMessage;
use super::builtin::{Header, TIME, Time, header_deps};
use super::geometry::{
    POSE_STAMPED, POSE_WITH_COVARIANCE, Pose, PoseStamped, PoseWithCovariance, TWIST,
    TWIST_WITH_COVARIANCE, TwistWithCovariance, VECTOR3, pose_deps,
};

/// nav_msgs/msg/Odometry: a base's pose in `odom` and its velocity in `base_link`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Odometry {
    pub header: Header,
    pub child_frame_id: String,
    pub pose: PoseWithCovariance,
    pub twist: TwistWithCovariance,
}

impl RosMessage for Odometry {
    const TYPE: &'static str = "nav_msgs/msg/Odometry";
    const DEFINITION: &'static str = "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\ngeometry_msgs/TwistWithCovariance twist\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        let mut deps = header_deps();
        deps.push(("geometry_msgs/msg/PoseWithCovariance", POSE_WITH_COVARIANCE));
        deps.extend(pose_deps());
        deps.extend([
            (
                "geometry_msgs/msg/TwistWithCovariance",
                TWIST_WITH_COVARIANCE,
            ),
            ("geometry_msgs/msg/Twist", TWIST),
            ("geometry_msgs/msg/Vector3", VECTOR3),
        ]);
        deps
    }
}

/// nav_msgs/msg/MapMetaData.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct MapMetaData {
    pub map_load_time: Time,
    pub resolution: f32,
    pub width: u32,
    pub height: u32,
    pub origin: Pose,
}

/// nav_msgs/msg/OccupancyGrid: 0 free, 100 occupied, -1 unknown; row-major from the origin.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct OccupancyGrid {
    pub header: Header,
    pub info: MapMetaData,
    pub data: Vec<i8>,
}

const MAP_META_DATA: &str = "builtin_interfaces/Time map_load_time\nfloat32 resolution\nuint32 width\nuint32 height\ngeometry_msgs/Pose origin\n";

impl RosMessage for OccupancyGrid {
    const TYPE: &'static str = "nav_msgs/msg/OccupancyGrid";
    const DEFINITION: &'static str = "std_msgs/Header header\nMapMetaData info\nint8[] data\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        let mut deps = header_deps();
        deps.push(("nav_msgs/msg/MapMetaData", MAP_META_DATA));
        deps.extend(pose_deps());
        deps.push(("builtin_interfaces/msg/Time", TIME));
        deps
    }
}

/// nav_msgs/msg/Path: a planner's way-points.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Path {
    pub header: Header,
    pub poses: Vec<PoseStamped>,
}

impl RosMessage for Path {
    const TYPE: &'static str = "nav_msgs/msg/Path";
    const DEFINITION: &'static str = "std_msgs/Header header\ngeometry_msgs/PoseStamped[] poses\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        let mut deps = header_deps();
        deps.push(("geometry_msgs/msg/PoseStamped", POSE_STAMPED));
        deps.extend(pose_deps());
        deps
    }
}

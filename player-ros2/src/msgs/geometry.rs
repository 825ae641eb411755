//! geometry_msgs and tf2_msgs: points, poses, twists and transforms.

use serde::{Deserialize, Serialize};

use super::builtin::{Header, header_deps};
use super::{Covariance, RosMessage};

#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Vector3 {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Point {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Quaternion {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub w: f64,
}

impl Default for Quaternion {
    fn default() -> Self {
        Quaternion::yaw(0.0)
    }
}

impl Quaternion {
    /// A turn of `yaw` radians about z (REP-103: counter-clockwise from x).
    pub fn yaw(yaw: f64) -> Quaternion {
        let (s, c) = (yaw / 2.0).sin_cos();
        Quaternion {
            x: 0.0,
            y: 0.0,
            z: s,
            w: c,
        }
    }
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Pose {
    pub position: Point,
    pub orientation: Quaternion,
}

impl Pose {
    /// A pose in the plane: (x, y) metres, facing `yaw`.
    pub fn planar(x: f64, y: f64, yaw: f64) -> Pose {
        Pose {
            position: Point { x, y, z: 0.0 },
            orientation: Quaternion::yaw(yaw),
        }
    }
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct PoseWithCovariance {
    pub pose: Pose,
    pub covariance: Covariance,
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Twist {
    pub linear: Vector3,
    pub angular: Vector3,
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct TwistWithCovariance {
    pub twist: Twist,
    pub covariance: Covariance,
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Transform {
    pub translation: Vector3,
    pub rotation: Quaternion,
}

#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct TransformStamped {
    pub header: Header,
    pub child_frame_id: String,
    pub transform: Transform,
}

/// tf2_msgs/msg/TFMessage: what `/tf` and `/tf_static` carry.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[allow(clippy::upper_case_acronyms)]
pub struct TFMessage {
    pub transforms: Vec<TransformStamped>,
}

/// geometry_msgs/msg/PoseStamped: a planner's goal, a path's way-point.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct PoseStamped {
    pub header: Header,
    pub pose: Pose,
}

/// geometry_msgs/msg/PoseWithCovarianceStamped: a localizer's estimate (`amcl_pose`).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct PoseWithCovarianceStamped {
    pub header: Header,
    pub pose: PoseWithCovariance,
}

pub const VECTOR3: &str = "float64 x\nfloat64 y\nfloat64 z\n";
pub const POINT: &str = "float64 x\nfloat64 y\nfloat64 z\n";
pub const QUATERNION: &str = "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n";
pub const POSE: &str = "Point position\nQuaternion orientation\n";
pub const POSE_WITH_COVARIANCE: &str = "Pose pose\nfloat64[36] covariance\n";
pub const TWIST: &str = "Vector3  linear\nVector3  angular\n";
pub const TWIST_WITH_COVARIANCE: &str = "Twist twist\nfloat64[36] covariance\n";
pub const TRANSFORM: &str = "Vector3 translation\nQuaternion rotation\n";
pub const TRANSFORM_STAMPED: &str =
    "std_msgs/Header header\nstring child_frame_id\nTransform transform\n";
pub const POSE_STAMPED: &str = "std_msgs/Header header\nPose pose\n";

/// Pose's own dependencies.
pub fn pose_deps() -> Vec<(&'static str, &'static str)> {
    vec![
        ("geometry_msgs/msg/Pose", POSE),
        ("geometry_msgs/msg/Point", POINT),
        ("geometry_msgs/msg/Quaternion", QUATERNION),
    ]
}

impl RosMessage for TFMessage {
    const TYPE: &'static str = "tf2_msgs/msg/TFMessage";
    const DEFINITION: &'static str = "geometry_msgs/TransformStamped[] transforms\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        let mut deps = vec![("geometry_msgs/msg/TransformStamped", TRANSFORM_STAMPED)];
        deps.extend(header_deps());
        deps.extend([
            ("geometry_msgs/msg/Transform", TRANSFORM),
            ("geometry_msgs/msg/Vector3", VECTOR3),
            ("geometry_msgs/msg/Quaternion", QUATERNION),
        ]);
        deps
    }
}

impl RosMessage for PoseStamped {
    const TYPE: &'static str = "geometry_msgs/msg/PoseStamped";
    const DEFINITION: &'static str = POSE_STAMPED;
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        let mut deps = header_deps();
        deps.extend(pose_deps());
        deps
    }
}

impl RosMessage for PoseWithCovarianceStamped {
    const TYPE: &'static str = "geometry_msgs/msg/PoseWithCovarianceStamped";
    const DEFINITION: &'static str = "std_msgs/Header header\nPoseWithCovariance pose\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        let mut deps = header_deps();
        deps.push(("geometry_msgs/msg/PoseWithCovariance", POSE_WITH_COVARIANCE));
        deps.extend(pose_deps());
        deps
    }
}

impl RosMessage for Twist {
    const TYPE: &'static str = "geometry_msgs/msg/Twist";
    const DEFINITION: &'static str = TWIST;
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        vec![("geometry_msgs/msg/Vector3", VECTOR3)]
    }
}

/// geometry_msgs/msg/TwistStamped: Jazzy's `cmd_vel` (Nav2's and teleop's from Jazzy on).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct TwistStamped {
    pub header: Header,
    pub twist: Twist,
}

impl RosMessage for TwistStamped {
    const TYPE: &'static str = "geometry_msgs/msg/TwistStamped";
    const DEFINITION: &'static str = "std_msgs/Header header\nTwist twist\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        let mut deps = header_deps();
        deps.extend([
            ("geometry_msgs/msg/Twist", TWIST),
            ("geometry_msgs/msg/Vector3", VECTOR3),
        ]);
        deps
    }
}

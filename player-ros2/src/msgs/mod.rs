//! ROS 2's message types that Player's data becomes, as serde structs in the field order of
//! their `.msg` definitions (CDR writes fields in order, with no names). Each type also gives
//! its name and its definition as rosbag2 and Foxglove read it ([`RosMessage`]).

mod builtin;
mod geometry;
mod nav;
mod octets;
mod sensor;

pub use builtin::{Clock, Header, Time};
pub use geometry::{
    Point, Pose, PoseStamped, PoseWithCovariance, PoseWithCovarianceStamped, Quaternion, TFMessage,
    Transform, TransformStamped, Twist, TwistStamped, TwistWithCovariance, Vector3,
};
pub use nav::{MapMetaData, OccupancyGrid, Odometry, Path};
pub use sensor::{
    BatteryState, CameraInfo, CompressedImage, Image, LaserScan, POINT_FIELD_FLOAT32,
    POWER_SUPPLY_STATUS_CHARGING, POWER_SUPPLY_STATUS_DISCHARGING, POWER_SUPPLY_STATUS_UNKNOWN,
    PointCloud2, PointField, RegionOfInterest,
};

/// A ROS 2 message type.
pub trait RosMessage: serde::Serialize {
    /// `pkg/msg/Type`, as `ros2 topic` and rosbag2 name it.
    const TYPE: &'static str;
    /// The type's `.msg` definition.
    const DEFINITION: &'static str;
    /// The types its fields use, each with its definition, for the schema of a file.
    fn dependencies() -> Vec<(&'static str, &'static str)>;
}

/// The schema rosbag2 (MCAP, encoding `ros2msg`) and Foxglove read: the type's definition,
/// then each type it uses after a line of `=` and `MSG: pkg/Type`.
pub fn schema_text<T: RosMessage>() -> String {
    let mut text = T::DEFINITION.trim_end().to_string();
    let mut seen: Vec<&str> = Vec::new();
    for (name, definition) in T::dependencies() {
        if seen.contains(&name) {
            continue;
        }
        seen.push(name);
        text.push_str(
            "\n================================================================================\n",
        );
        text.push_str(&format!("MSG: {}\n", name.replace("/msg/", "/")));
        text.push_str(definition.trim_end());
    }
    text.push('\n');
    text
}

/// The 36 numbers of a 6 x 6 covariance, row by row (serde writes arrays of at most 32
/// elements, so as six rows of six: the same 36 numbers in CDR).
pub type Covariance = [[f64; 6]; 6];

/// A covariance with `diagonal` down its diagonal.
pub fn covariance(diagonal: [f64; 6]) -> Covariance {
    let mut rows = [[0.0; 6]; 6];
    for (i, value) in diagonal.into_iter().enumerate() {
        rows[i][i] = value;
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_schema_is_the_definition_then_each_dependency_once() {
        let text = schema_text::<Odometry>();
        assert!(text.starts_with("std_msgs/Header header\nstring child_frame_id\n"));
        assert_eq!(text.matches("\nMSG: geometry_msgs/Quaternion\n").count(), 1);
        assert_eq!(text.matches("MSG: ").count(), 9, "{text}");
        assert!(text.contains("MSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec\n"));
    }

    #[test]
    fn a_covariance_is_thirty_six_numbers() {
        let bytes = crate::cdr::serialize(&covariance([1.0; 6])).unwrap();
        assert_eq!(bytes.len(), 4 + 36 * 8);
    }
}

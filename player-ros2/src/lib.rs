//! Player robots in ROS 2's vocabulary: what the ROS 2 front and rosbag2 files share.
//!
//! * [`msgs`] — ROS 2's message types, with their definitions, as serde structs.
//! * [`cdr`] — their serialized form (CDR, little-endian, with its encapsulation header).
//! * [`names`] — a robot's namespace, topics and frames.
//! * [`convert`] — Player's messages as ROS 2's ([`out`]: what it makes; [`converter`]: one
//!   robot's, remembering what its devices said of themselves); [`map`] a Player map
//!   as an occupancy grid; [`camera`] a picture as an image; [`ranges`] sonar and ranger
//!   arrays as point clouds.
//! * [`bag`] — a recording as a rosbag2 folder (MCAP with `ros2msg` schemas, `metadata.yaml`).
//! * `live` (feature `live`, on by default) — each robot a ROS 2 node over DDS.

pub mod bag;
pub mod camera;
pub mod cdr;
pub mod convert;
pub mod converter;
#[cfg(feature = "live")]
pub mod live;
pub mod map;
pub mod msgs;
pub mod names;
pub mod out;
pub mod ranges;

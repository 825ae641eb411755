//! sensor_msgs: laser scans, batteries, pictures and their cameras, point clouds.

use serde::{Deserialize, Serialize};

use super::RosMessage;
use super::builtin::{Header, header_deps};

/// sensor_msgs/msg/LaserScan: ranges counter-clockwise from `angle_min`, metres.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct LaserScan {
    pub header: Header,
    pub angle_min: f32,
    pub angle_max: f32,
    pub angle_increment: f32,
    pub time_increment: f32,
    pub scan_time: f32,
    pub range_min: f32,
    pub range_max: f32,
    pub ranges: Vec<f32>,
    pub intensities: Vec<f32>,
}

impl RosMessage for LaserScan {
    const TYPE: &'static str = "sensor_msgs/msg/LaserScan";
    const DEFINITION: &'static str = "std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\nfloat32 time_increment\nfloat32 scan_time\nfloat32 range_min\nfloat32 range_max\nfloat32[] ranges\nfloat32[] intensities\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        header_deps()
    }
}

/// sensor_msgs/msg/BatteryState.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct BatteryState {
    pub header: Header,
    pub voltage: f32,
    pub temperature: f32,
    pub current: f32,
    pub charge: f32,
    pub capacity: f32,
    pub design_capacity: f32,
    pub percentage: f32,
    pub power_supply_status: u8,
    pub power_supply_health: u8,
    pub power_supply_technology: u8,
    pub present: bool,
    pub cell_voltage: Vec<f32>,
    pub cell_temperature: Vec<f32>,
    pub location: String,
    pub serial_number: String,
}

/// BatteryState's `power_supply_status` values.
pub const POWER_SUPPLY_STATUS_UNKNOWN: u8 = 0;
pub const POWER_SUPPLY_STATUS_CHARGING: u8 = 1;
pub const POWER_SUPPLY_STATUS_DISCHARGING: u8 = 2;

impl RosMessage for BatteryState {
    const TYPE: &'static str = "sensor_msgs/msg/BatteryState";
    const DEFINITION: &'static str = "uint8 POWER_SUPPLY_STATUS_UNKNOWN = 0\nuint8 POWER_SUPPLY_STATUS_CHARGING = 1\nuint8 POWER_SUPPLY_STATUS_DISCHARGING = 2\nuint8 POWER_SUPPLY_STATUS_NOT_CHARGING = 3\nuint8 POWER_SUPPLY_STATUS_FULL = 4\nuint8 POWER_SUPPLY_HEALTH_UNKNOWN = 0\nuint8 POWER_SUPPLY_HEALTH_GOOD = 1\nuint8 POWER_SUPPLY_HEALTH_OVERHEAT = 2\nuint8 POWER_SUPPLY_HEALTH_DEAD = 3\nuint8 POWER_SUPPLY_HEALTH_OVERVOLTAGE = 4\nuint8 POWER_SUPPLY_HEALTH_UNSPEC_FAILURE = 5\nuint8 POWER_SUPPLY_HEALTH_COLD = 6\nuint8 POWER_SUPPLY_HEALTH_WATCHDOG_TIMER_EXPIRE = 7\nuint8 POWER_SUPPLY_HEALTH_SAFETY_TIMER_EXPIRE = 8\nuint8 POWER_SUPPLY_TECHNOLOGY_UNKNOWN = 0\nuint8 POWER_SUPPLY_TECHNOLOGY_NIMH = 1\nuint8 POWER_SUPPLY_TECHNOLOGY_LION = 2\nuint8 POWER_SUPPLY_TECHNOLOGY_LIPO = 3\nuint8 POWER_SUPPLY_TECHNOLOGY_LIFE = 4\nuint8 POWER_SUPPLY_TECHNOLOGY_NICD = 5\nuint8 POWER_SUPPLY_TECHNOLOGY_LIMN = 6\nstd_msgs/Header header\nfloat32 voltage\nfloat32 temperature\nfloat32 current\nfloat32 charge\nfloat32 capacity\nfloat32 design_capacity\nfloat32 percentage\nuint8 power_supply_status\nuint8 power_supply_health\nuint8 power_supply_technology\nbool present\nfloat32[] cell_voltage\nfloat32[] cell_temperature\nstring location\nstring serial_number\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        header_deps()
    }
}

/// sensor_msgs/msg/Image: raw pixels, row by row.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Image {
    pub header: Header,
    pub height: u32,
    pub width: u32,
    /// `rgb8`, `mono8`, `mono16`, ...
    pub encoding: String,
    pub is_bigendian: u8,
    /// Bytes per row.
    pub step: u32,
    #[serde(with = "super::octets")]
    pub data: Vec<u8>,
}

impl RosMessage for Image {
    const TYPE: &'static str = "sensor_msgs/msg/Image";
    const DEFINITION: &'static str = "std_msgs/Header header\nuint32 height\nuint32 width\nstring encoding\nuint8 is_bigendian\nuint32 step\nuint8[] data\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        header_deps()
    }
}

/// sensor_msgs/msg/CompressedImage: a whole JPEG (or PNG) file.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct CompressedImage {
    pub header: Header,
    /// `jpeg` or `png`.
    pub format: String,
    #[serde(with = "super::octets")]
    pub data: Vec<u8>,
}

impl RosMessage for CompressedImage {
    const TYPE: &'static str = "sensor_msgs/msg/CompressedImage";
    const DEFINITION: &'static str = "std_msgs/Header header\nstring format\nuint8[] data\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        header_deps()
    }
}

/// sensor_msgs/msg/RegionOfInterest: a part of a picture (all zeros: the whole of it).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct RegionOfInterest {
    pub x_offset: u32,
    pub y_offset: u32,
    pub height: u32,
    pub width: u32,
    pub do_rectify: bool,
}

const REGION_OF_INTEREST: &str =
    "uint32 x_offset\nuint32 y_offset\nuint32 height\nuint32 width\nbool do_rectify\n";

/// sensor_msgs/msg/CameraInfo: a picture's size and its camera's calibration; `k`, `r` and
/// `p` all zeros say "uncalibrated", as ROS's image pipeline reads them.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct CameraInfo {
    pub header: Header,
    pub height: u32,
    pub width: u32,
    pub distortion_model: String,
    pub d: Vec<f64>,
    pub k: [f64; 9],
    pub r: [f64; 9],
    pub p: [f64; 12],
    pub binning_x: u32,
    pub binning_y: u32,
    pub roi: RegionOfInterest,
}

impl RosMessage for CameraInfo {
    const TYPE: &'static str = "sensor_msgs/msg/CameraInfo";
    const DEFINITION: &'static str = "std_msgs/Header header\nuint32 height\nuint32 width\nstring distortion_model\nfloat64[] d\nfloat64[9]  k\nfloat64[9]  r\nfloat64[12] p\nuint32 binning_x\nuint32 binning_y\nRegionOfInterest roi\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        let mut deps = header_deps();
        deps.push(("sensor_msgs/msg/RegionOfInterest", REGION_OF_INTEREST));
        deps
    }
}

/// sensor_msgs/msg/PointField: one field of a point cloud's points.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct PointField {
    pub name: String,
    /// Bytes from the start of the point.
    pub offset: u32,
    pub datatype: u8,
    pub count: u32,
}

/// PointField's `datatype` of a 32-bit float.
pub const POINT_FIELD_FLOAT32: u8 = 7;

const POINT_FIELD: &str = "uint8 INT8    = 1\nuint8 UINT8   = 2\nuint8 INT16   = 3\nuint8 UINT16  = 4\nuint8 INT32   = 5\nuint8 UINT32  = 6\nuint8 FLOAT32 = 7\nuint8 FLOAT64 = 8\nstring name\nuint32 offset\nuint8  datatype\nuint32 count\n";

/// sensor_msgs/msg/PointCloud2: points as packed bytes, `point_step` bytes each.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct PointCloud2 {
    pub header: Header,
    pub height: u32,
    pub width: u32,
    pub fields: Vec<PointField>,
    pub is_bigendian: bool,
    pub point_step: u32,
    pub row_step: u32,
    #[serde(with = "super::octets")]
    pub data: Vec<u8>,
    pub is_dense: bool,
}

impl RosMessage for PointCloud2 {
    const TYPE: &'static str = "sensor_msgs/msg/PointCloud2";
    const DEFINITION: &'static str = "std_msgs/Header header\nuint32 height\nuint32 width\nPointField[] fields\nbool    is_bigendian\nuint32  point_step\nuint32  row_step\nuint8[] data\nbool is_dense\n";
    fn dependencies() -> Vec<(&'static str, &'static str)> {
        let mut deps = header_deps();
        deps.push(("sensor_msgs/msg/PointField", POINT_FIELD));
        deps
    }
}

//! The `laser` interface (code 6). Deprecated in Player 3 in favour of `ranger`, but what most
//! real robots and Player's `rangertolaser` driver serve.
//!
//! Reading `i` of a scan lies at bearing `min_angle + i * resolution`, counter-clockwise, 0 rad
//! straight ahead of the sensor. Ranges are `f32`; intensities one byte each.

use super::common::{BBox3d, Pose2d, Pose3d};
use crate::wire::Opaque;

/// `PLAYER_LASER_MAX_FILTER_PARAMS`.
pub const MAX_FILTER_PARAMS: u32 = 8;
pub const FILTER_MEDIAN: u8 = 1;
pub const FILTER_EDGE: u8 = 2;
pub const FILTER_RANGE: u8 = 3;
pub const FILTER_MEAN: u8 = 4;

/// Request subtypes whose request body is empty (the ACK carries the structure).
pub const REQ_GET_GEOM: u8 = 1;
pub const REQ_GET_CONFIG: u8 = 3;
pub const REQ_GET_ID: u8 = 5;

xdr_struct! {
    /// `player_laser_data_t`: one scan.
    pub struct LaserScan {
        /// Bearing of the first reading, rad.
        pub min_angle: f32,
        /// Bearing of the last reading, rad.
        pub max_angle: f32,
        /// Angle between readings, rad.
        pub resolution: f32,
        /// m.
        pub max_range: f32,
        /// m, one per beam.
        pub ranges: Vec<f32>,
        /// One byte per beam, or none; meaning is device-specific.
        pub intensity: Opaque,
        /// Scan sequence number.
        pub id: u32,
    }
}

xdr_struct! {
    /// `player_laser_data_scanpose_t`: a scan and the laser's global pose when it was taken.
    pub struct LaserScanPose {
        pub scan: LaserScan,
        pub pose: Pose2d,
    }
}

xdr_struct! {
    /// `player_laser_data_scanangle_t`: a scan with an explicit bearing per reading.
    pub struct LaserScanAngle {
        pub max_range: f32,
        pub ranges: Vec<f32>,
        pub angles: Vec<f32>,
        pub intensity: Opaque,
        pub id: u32,
    }
}

xdr_struct! {
    /// `player_laser_geom_t`: where the laser sits on the robot, and its size.
    pub struct LaserGeometry {
        pub pose: Pose3d,
        pub size: BBox3d,
    }
}

xdr_struct! {
    /// `player_laser_config_t`.
    pub struct LaserConfig {
        pub min_angle: f32,
        pub max_angle: f32,
        pub resolution: f32,
        pub max_range: f32,
        pub range_res: f32,
        /// 1 = intensity data enabled.
        pub intensity: u8,
        /// Hz.
        pub scanning_frequency: f32,
    }
}

xdr_struct! {
    /// `player_laser_power_config_t`: 0 = off, 1 = on.
    pub struct LaserPower {
        pub state: u8,
    }
}

xdr_struct! {
    /// `player_laser_get_id_config_t`.
    pub struct LaserId {
        pub serial_number: u32,
    }
}

xdr_struct! {
    /// `player_laser_set_filter_config_t`: at most 8 parameters.
    pub struct LaserFilter {
        pub filter_type: u8,
        #[cfg_attr(any(test, feature = "proptest"), proptest(strategy = "proptest::collection::vec(proptest::arbitrary::any::<f32>(), 0..=8)"))]
        pub parameters: Vec<f32> [max MAX_FILTER_PARAMS],
    }
}

interface_messages! {
    /// Messages of the `laser` interface.
    pub enum Laser for LASER {
        Data 1 as DATA_SCAN => Scan(LaserScan),
        Data 2 as DATA_SCANPOSE => ScanPose(LaserScanPose),
        Data 3 as DATA_SCANANGLE => ScanAngle(LaserScanAngle),
        Request 1 as REQ_GET_GEOM => Geometry(LaserGeometry),
        Request 2 as REQ_SET_CONFIG => SetConfig(LaserConfig),
        Request 3 as REQ_GET_CONFIG => Config(LaserConfig),
        Request 4 as REQ_POWER => Power(LaserPower),
        Request 5 as REQ_GET_ID => Id(LaserId),
        Request 6 as REQ_SET_FILTER => SetFilter(LaserFilter),
    }
}

impl LaserScan {
    /// Bearing of reading `i`, rad.
    pub fn bearing(&self, i: usize) -> f32 {
        self.min_angle + i as f32 * self.resolution
    }
}

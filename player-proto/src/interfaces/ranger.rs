//! The `ranger` interface (code 62): Player 3's generic range sensor, and what Stage 4 serves
//! its lasers and sonars as. Ranges and intensities are `f64`.
//!
//! With one element in the geometry, reading `i` lies at `min_angle + i * angular_res`; with N
//! elements, reading `i` belongs to element `i` and points along its pose.

use super::common::{BBox3d, Pose3d};

/// Request subtypes whose request body is empty.
pub const REQ_GET_GEOM: u8 = 1;
pub const REQ_GET_CONFIG: u8 = 5;

xdr_struct! {
    /// `player_ranger_config_t`.
    #[derive(Copy)]
    pub struct RangerConfig {
        pub min_angle: f64,
        pub max_angle: f64,
        pub angular_res: f64,
        pub min_range: f64,
        pub max_range: f64,
        pub range_res: f64,
        /// Hz.
        pub frequency: f64,
    }
}

xdr_struct! {
    /// `player_ranger_geom_t`: device pose and size, and per-element poses and sizes.
    pub struct RangerGeometry {
        pub pose: Pose3d,
        pub size: BBox3d,
        pub element_poses: Vec<Pose3d>,
        pub element_sizes: Vec<BBox3d>,
    }
}

xdr_struct! {
    /// `player_ranger_data_range_t`: m.
    pub struct RangerRanges {
        pub ranges: Vec<f64>,
    }
}

xdr_struct! {
    /// `player_ranger_data_intns_t`: device-specific units.
    pub struct RangerIntensities {
        pub intensities: Vec<f64>,
    }
}

xdr_struct! {
    /// `player_ranger_data_rangestamped_t`: ranges with the geometry and config in force
    /// (both always encoded, meaningful only when their flag is set).
    pub struct RangerRangesStamped {
        pub data: RangerRanges,
        pub have_geom: u8,
        pub geom: RangerGeometry,
        pub have_config: u8,
        pub config: RangerConfig,
    }
}

xdr_struct! {
    /// `player_ranger_data_intnsstamped_t`.
    pub struct RangerIntensitiesStamped {
        pub data: RangerIntensities,
        pub have_geom: u8,
        pub geom: RangerGeometry,
        pub have_config: u8,
        pub config: RangerConfig,
    }
}

xdr_struct! {
    /// `player_ranger_power_config_t` and `player_ranger_intns_config_t`: 0 = off, 1 = on.
    #[derive(Copy)]
    pub struct RangerSwitch {
        pub state: u8,
    }
}

interface_messages! {
    /// Messages of the `ranger` interface.
    pub enum Ranger for RANGER {
        Data 1 as DATA_RANGE => Ranges(RangerRanges),
        // Boxed: 208 bytes inline would make every `Body` that size (see `stored!`).
        Data 2 as DATA_RANGESTAMPED => RangesStamped(RangerRangesStamped, boxed),
        Data 3 as DATA_INTNS => Intensities(RangerIntensities),
        Data 4 as DATA_INTNSSTAMPED => IntensitiesStamped(RangerIntensitiesStamped, boxed),
        Data 5 as DATA_GEOM => GeometryData(RangerGeometry),
        Request 1 as REQ_GET_GEOM => Geometry(RangerGeometry),
        Request 2 as REQ_POWER => Power(RangerSwitch),
        Request 3 as REQ_INTNS => IntensityMode(RangerSwitch),
        Request 4 as REQ_SET_CONFIG => SetConfig(RangerConfig),
        Request 5 as REQ_GET_CONFIG => Config(RangerConfig),
    }
}

impl RangerConfig {
    /// Bearing of reading `i` of a single-element (laser-like) ranger, rad.
    pub fn bearing(&self, i: usize) -> f64 {
        self.min_angle + i as f64 * self.angular_res
    }
}

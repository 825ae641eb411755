//! The `bumper` interface (code 14): contact switches.

use super::common::Pose3d;
use crate::wire::Opaque;

pub const REQ_GET_GEOM: u8 = 1;

xdr_struct! {
    /// `player_bumper_data_t`: one byte per bumper, non-zero = pressed.
    pub struct BumperData {
        pub bumpers: Opaque,
    }
}

xdr_struct! {
    /// `player_bumper_define_t`: where a bumper is, its length and curvature radius (0 = straight).
    #[derive(Copy)]
    pub struct BumperDefine {
        pub pose: Pose3d,
        pub length: f32,
        pub radius: f32,
    }
}

xdr_struct! {
    /// `player_bumper_geom_t`.
    pub struct BumperGeometry {
        pub bumper_def: Vec<BumperDefine>,
    }
}

interface_messages! {
    /// Messages of the `bumper` interface.
    pub enum Bumper for BUMPER {
        Data 1 as DATA_STATE => State(BumperData),
        Data 2 as DATA_GEOM => GeometryData(BumperGeometry),
        Request 1 as REQ_GET_GEOM => Geometry(BumperGeometry),
    }
}

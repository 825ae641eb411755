//! The `sonar` interface (code 5): a ring of range transducers. Deprecated in Player 3 in
//! favour of `ranger`, still served by many robot drivers.

use super::common::Pose3d;

/// Request subtype whose request body is empty (the ACK carries the geometry).
pub const REQ_GET_GEOM: u8 = 1;

xdr_struct! {
    /// `player_sonar_data_t`: one range per transducer, m.
    pub struct SonarData {
        pub ranges: Vec<f32>,
    }
}

xdr_struct! {
    /// `player_sonar_geom_t`: one pose per transducer, robot frame.
    pub struct SonarGeometry {
        pub poses: Vec<Pose3d>,
    }
}

xdr_struct! {
    /// `player_sonar_power_config_t`: 0 = off, 1 = on.
    pub struct SonarPower {
        pub state: u8,
    }
}

interface_messages! {
    /// Messages of the `sonar` interface.
    pub enum Sonar for SONAR {
        Data 1 as DATA_RANGES => Ranges(SonarData),
        Data 2 as DATA_GEOM => GeometryData(SonarGeometry),
        Request 1 as REQ_GET_GEOM => Geometry(SonarGeometry),
        Request 2 as REQ_POWER => Power(SonarPower),
    }
}

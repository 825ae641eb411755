//! The `ptz` interface (code 8): a pan-tilt-zoom unit, usually carrying a camera.
//!
//! Commands are absolute: a pan of 0.5 rad turns the unit to 0.5 rad, not by it. Whether the
//! speeds are targets or limits depends on the control mode (`REQ_CONTROL_MODE`), which
//! changes how the driver reads every client's commands.

use super::common::{BBox3d, Pose3d};

/// `PLAYER_PTZ_VELOCITY_CONTROL`: commands drive the speeds.
pub const VELOCITY_CONTROL: u32 = 0;
/// `PLAYER_PTZ_POSITION_CONTROL`: commands set the angles, speeds are limits.
pub const POSITION_CONTROL: u32 = 1;

/// Request subtypes whose request body is empty (the ACK carries the structure).
pub const REQ_GEOM: u8 = 4;
pub const REQ_STATUS: u8 = 5;

xdr_struct! {
    /// `player_ptz_data_t`.
    #[derive(Copy)]
    pub struct PtzData {
        /// rad.
        pub pan: f32,
        /// rad.
        pub tilt: f32,
        /// Field of view, rad.
        pub zoom: f32,
        /// rad/s.
        pub panspeed: f32,
        /// rad/s.
        pub tiltspeed: f32,
        /// Driver-specific status bits.
        pub status: u32,
    }
}

xdr_struct! {
    /// `player_ptz_cmd_t`.
    #[derive(Copy)]
    pub struct PtzCmd {
        /// rad.
        pub pan: f32,
        /// rad.
        pub tilt: f32,
        /// Field of view, rad.
        pub zoom: f32,
        /// rad/s.
        pub panspeed: f32,
        /// rad/s.
        pub tiltspeed: f32,
    }
}

xdr_struct! {
    /// `player_ptz_req_status_t`: the driver-specific status word.
    #[derive(Copy)]
    pub struct PtzStatus {
        pub status: u32,
    }
}

xdr_struct! {
    /// `player_ptz_geom_t`: where the unit sits on the robot, and its size.
    #[derive(Copy)]
    pub struct PtzGeometry {
        pub pos: Pose3d,
        pub size: BBox3d,
    }
}

xdr_struct! {
    /// `player_ptz_req_generic_t`: unit-specific words; the reply may carry words back.
    pub struct PtzGeneric {
        pub config: Vec<u32>,
    }
}

xdr_struct! {
    /// `player_ptz_req_control_mode_t` (null reply).
    #[derive(Copy)]
    pub struct PtzControlMode {
        /// [`VELOCITY_CONTROL`] or [`POSITION_CONTROL`].
        pub mode: u32,
    }
}

interface_messages! {
    /// Messages of the `ptz` interface (request subtype 3 is unused by Player).
    pub enum Ptz for PTZ {
        Data 1 as DATA_STATE => State(PtzData),
        Data 2 as DATA_GEOM => GeometryData(PtzGeometry),
        Command 1 as CMD_STATE => Command(PtzCmd),
        Request 1 as REQ_GENERIC => Generic(PtzGeneric),
        Request 2 as REQ_CONTROL_MODE => ControlMode(PtzControlMode),
        Request 4 as REQ_GEOM => Geometry(PtzGeometry),
        Request 5 as REQ_STATUS => Status(PtzStatus),
    }
}

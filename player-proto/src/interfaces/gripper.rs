//! The `gripper` interface (code 3). OPEN, CLOSE, STOP, STORE and RETRIEVE (commands 1–5) have
//! no body.

use super::common::{BBox3d, Pose3d};

pub const CMD_OPEN: u8 = 1;
pub const CMD_CLOSE: u8 = 2;
pub const CMD_STOP: u8 = 3;
pub const CMD_STORE: u8 = 4;
pub const CMD_RETRIEVE: u8 = 5;
pub const REQ_GET_GEOM: u8 = 1;

pub const STATE_OPEN: u8 = 1;
pub const STATE_CLOSED: u8 = 2;
pub const STATE_MOVING: u8 = 3;
pub const STATE_ERROR: u8 = 4;

xdr_struct! {
    /// `player_gripper_data_t`.
    #[derive(Copy)]
    pub struct GripperData {
        /// `STATE_*`.
        pub state: u8,
        /// Break-beam bitmask.
        pub beams: u32,
        pub stored: u8,
    }
}

xdr_struct! {
    /// `player_gripper_geom_t`.
    #[derive(Copy)]
    pub struct GripperGeometry {
        pub pose: Pose3d,
        pub outer_size: BBox3d,
        pub inner_size: BBox3d,
        pub num_beams: u8,
        pub capacity: u8,
    }
}

interface_messages! {
    /// Messages of the `gripper` interface.
    pub enum Gripper for GRIPPER {
        Data 1 as DATA_STATE => State(GripperData),
        Request 1 as REQ_GET_GEOM => Geometry(GripperGeometry),
    }
}

//! The `gripper` interface (code 3). OPEN, CLOSE, STOP, STORE and RETRIEVE (commands 1–5) have
//! no body: they are typed here with [`GripperSignal`], an empty structure, so that a client
//! sends them by name like any other command.

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

xdr_struct! {
    /// The body of the gripper's commands, which carry nothing: the subtype is the order.
    #[derive(Copy)]
    pub struct GripperSignal {}
}

interface_messages! {
    /// Messages of the `gripper` interface.
    pub enum Gripper for GRIPPER {
        Data 1 as DATA_STATE => State(GripperData),
        Command 1 as CMD_OPEN => Open(GripperSignal),
        Command 2 as CMD_CLOSE => Close(GripperSignal),
        Command 3 as CMD_STOP => Stop(GripperSignal),
        Command 4 as CMD_STORE => Store(GripperSignal),
        Command 5 as CMD_RETRIEVE => Retrieve(GripperSignal),
        Request 1 as REQ_GET_GEOM => Geometry(GripperGeometry),
    }
}

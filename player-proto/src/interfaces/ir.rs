//! The `ir` interface (code 22): an array of infrared range sensors. Deprecated in Player 3 in
//! favour of `ranger`, but what older robot drivers (Roomba, Create, Khepera) still serve.

use super::common::{BoolValue, Pose3d};

/// Request subtype whose request body is empty (the ACK carries the poses).
pub const REQ_POSE: u8 = 1;

xdr_struct! {
    /// `player_ir_data_t`: one reading per sensor, as the raw voltage and as a range.
    pub struct IrData {
        /// V.
        pub voltages: Vec<f32>,
        /// m.
        pub ranges: Vec<f32>,
    }
}

xdr_struct! {
    /// `player_ir_pose_t`: where each sensor sits on the robot.
    pub struct IrPose {
        pub poses: Vec<Pose3d>,
    }
}

/// `player_ir_power_req_t`: 1 = on, 0 = off (null reply).
pub type IrPower = BoolValue;

interface_messages! {
    /// Messages of the `ir` interface.
    pub enum Ir for IR {
        Data 1 as DATA_RANGES => Ranges(IrData),
        Request 1 as REQ_POSE => Pose(IrPose),
        Request 2 as REQ_POWER => Power(IrPower),
    }
}

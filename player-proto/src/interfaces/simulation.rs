//! The `simulation` interface (code 31): a simulator's models, addressed by name.
//! PAUSE, RESET and SAVE commands (subtypes 1–3) have no body.

use super::common::{Pose2d, Pose3d};
use crate::wire::{Opaque, PlayerString};

pub const CMD_PAUSE: u8 = 1;
pub const CMD_RESET: u8 = 2;
pub const CMD_SAVE: u8 = 3;

xdr_struct! {
    /// `player_simulation_pose2d_req_t`: a model's pose in the plane. libplayerc sends the pose
    /// uninitialised in GET requests.
    pub struct SimulationPose2d {
        pub name: PlayerString,
        pub pose: Pose2d,
    }
}

xdr_struct! {
    /// `player_simulation_pose3d_req_t`.
    pub struct SimulationPose3d {
        pub name: PlayerString,
        pub pose: Pose3d,
        /// Simulation time, s.
        pub simtime: f64,
    }
}

xdr_struct! {
    /// `player_simulation_property_req_t`: the value is raw bytes in the simulator host's own
    /// representation, not XDR.
    pub struct SimulationProperty {
        pub name: PlayerString,
        pub prop: PlayerString,
        pub index: u32,
        pub value: Opaque,
    }
}

interface_messages! {
    /// Messages of the `simulation` interface.
    pub enum Simulation for SIMULATION {
        Request 1 as REQ_GET_POSE2D => Pose2d(SimulationPose2d),
        Request 2 as REQ_SET_POSE2D => SetPose2d(SimulationPose2d),
        Request 3 as REQ_GET_POSE3D => Pose3d(SimulationPose3d),
        Request 4 as REQ_SET_POSE3D => SetPose3d(SimulationPose3d),
        Request 5 as REQ_GET_PROPERTY => Property(SimulationProperty),
        Request 6 as REQ_SET_PROPERTY => SetProperty(SimulationProperty),
    }
}

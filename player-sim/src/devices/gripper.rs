//! A Stage gripper as Player's Stage plugin serves it: its state (open, closed, moving) and
//! beams, its geometry on request, and the open and close commands. The plugin ignores the
//! other gripper commands (stop, store, retrieve), and so does player-sim.

use player_proto::interfaces::common::{BBox3d, Pose3d};
use player_proto::interfaces::gripper::{
    CMD_CLOSE, CMD_OPEN, GripperData, GripperGeometry, STATE_CLOSED, STATE_MOVING, STATE_OPEN,
};
use player_proto::message::Message;

use crate::sim::{GripperCommand, Paddles, Simulation};

/// Stage's gripper has two beams.
const BEAMS: u8 = 2;

pub(super) fn data(sim: &Simulation, robot: usize, gripper: usize) -> GripperData {
    let state = &sim.robots[robot].grippers[gripper];
    GripperData {
        state: match state.paddles {
            Paddles::Open => STATE_OPEN,
            Paddles::Closed => STATE_CLOSED,
            Paddles::Opening | Paddles::Closing => STATE_MOVING,
        },
        beams: state.beam_bits(),
        stored: 0,
    }
}

pub(super) fn geometry(sim: &Simulation, robot: usize, gripper: usize) -> GripperGeometry {
    let spec = &sim.world.robots[robot].grippers[gripper];
    GripperGeometry {
        pose: Pose3d {
            px: spec.pose.x,
            py: spec.pose.y,
            pyaw: spec.pose.a,
            ..Pose3d::default()
        },
        outer_size: BBox3d {
            sl: spec.size[0],
            sw: spec.size[1],
            sh: spec.size[2],
        },
        inner_size: BBox3d::default(),
        num_beams: BEAMS,
        capacity: 0,
    }
}

/// What a command tells the gripper, if anything.
pub(super) fn command(command: &Message) -> Option<GripperCommand> {
    match command.header.subtype {
        CMD_OPEN => Some(GripperCommand::Open),
        CMD_CLOSE => Some(GripperCommand::Close),
        other => {
            tracing::debug!("gripper command {other} ignored, as Stage ignores it");
            None
        }
    }
}

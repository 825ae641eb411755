//! Stage's gripper: paddles that open and close a twentieth of the way each update, two
//! break-beams across the gap between them, and contact rays along their inner faces. Closing
//! on something that can be gripped (`gripper_return 1`) picks it up: it then rides with the
//! gripper, out of its robot's own sensors' and collisions' way, until the paddles open again
//! and put it down where the gripper is.

use super::Simulation;
use super::body_pose::{body_at, on_robot};
use super::geometry::GroundBox;
use crate::world::{GripperSpec, Pose};

/// How far the paddles move in one update, as a part of the full stroke (Stage's).
const PADDLE_STEP: f64 = 0.05;
/// Where the two beams cross the paddles, as parts of the paddle length from the tip.
const BEAM_INSETS: [f64; 2] = [3.0 / 4.0, 1.0 / 4.0];
/// The bits Stage's plugin reports for the inner and the outer beam.
pub const BEAM_BITS: [u32; 2] = [0x04, 0x08];

/// What a client last told the gripper.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GripperCommand {
    None,
    Open,
    Close,
}

/// Where the paddles are going.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Paddles {
    Open,
    Closed,
    Opening,
    Closing,
}

/// A gripper's moving state.
#[derive(Debug, Clone, PartialEq)]
pub struct GripperState {
    pub paddles: Paddles,
    /// 0 open to 1 closed.
    pub position: f64,
    /// Where closing stops: 1, or less while holding something.
    pub close_limit: f64,
    /// The obstacle held.
    pub gripped: Option<usize>,
    /// Inner and outer beam broken.
    pub beams: [bool; 2],
    pub command: GripperCommand,
}

impl GripperState {
    pub fn new(spec: &GripperSpec) -> GripperState {
        GripperState {
            paddles: if spec.closed {
                Paddles::Closed
            } else {
                Paddles::Open
            },
            position: if spec.closed { 1.0 } else { 0.0 },
            close_limit: 1.0,
            gripped: None,
            beams: [false; 2],
            command: GripperCommand::None,
        }
    }

    /// The beams as Player's gripper data carries them.
    pub fn beam_bits(&self) -> u32 {
        self.beams
            .iter()
            .zip(BEAM_BITS)
            .filter(|(broken, _)| **broken)
            .map(|(_, bit)| bit)
            .sum()
    }
}

impl Simulation {
    /// Where robot `robot`'s gripper `gripper` is in the world.
    pub fn gripper_pose(&self, robot: usize, gripper: usize) -> Pose {
        on_robot(
            self.robots[robot].pose,
            self.world.robots[robot].grippers[gripper].pose,
        )
    }

    /// The nearest grippable obstacle along a ray, within `length`.
    fn grippable_along(&self, from: Pose, length: f64) -> Option<usize> {
        if length <= 0.0 {
            return None;
        }
        self.world
            .obstacles
            .iter()
            .enumerate()
            .filter(|(_, o)| o.gripper_return)
            .filter_map(|(i, o)| {
                let body = GroundBox {
                    pose: body_at(o.pose, o.origin),
                    length: o.size[0],
                    width: o.size[1],
                    shape: &o.shape,
                };
                body.raycast(from.x, from.y, from.a)
                    .filter(|d| *d <= length)
                    .map(|d| (d, i))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, i)| i)
    }

    /// One update of robot `robot`'s gripper `gripper`, as Stage's.
    pub(super) fn update_gripper(&mut self, robot: usize, gripper: usize) {
        let spec = self.world.robots[robot].grippers[gripper].clone();
        let at = self.gripper_pose(robot, gripper);
        let state = &mut self.robots[robot].grippers[gripper];
        match state.command {
            GripperCommand::Close if state.paddles != Paddles::Closed => {
                state.paddles = Paddles::Closing;
            }
            GripperCommand::Open if state.paddles != Paddles::Open => {
                state.paddles = Paddles::Opening;
            }
            _ => {}
        }
        let mut released = None;
        match state.paddles {
            Paddles::Opening => {
                state.position -= PADDLE_STEP;
                if state.position < 0.0 {
                    state.position = 0.0;
                    state.paddles = Paddles::Open;
                }
                if state.gripped.is_some()
                    && (state.position == 0.0 || state.position < state.close_limit)
                {
                    released = state.gripped.take();
                    state.close_limit = 1.0;
                }
            }
            Paddles::Closing => {
                state.position += PADDLE_STEP;
                if state.position > state.close_limit {
                    state.position = state.close_limit;
                    state.paddles = Paddles::Closed;
                }
            }
            Paddles::Open | Paddles::Closed => {}
        }
        if let Some(o) = released {
            self.world.obstacles[o].pose = at;
            self.carried_by[o] = None;
        }
        let open = 1.0 - self.robots[robot].grippers[gripper].position;
        let ([sx, sy, _], [px, py, _]) = (spec.size, spec.paddle_size);
        // The beams run across the gap, from the left paddle's inner face to the right one's.
        let gap_half = open * (sy / 2.0 - sy * py);
        let mut beams = [false; 2];
        for (beam, inset) in beams.iter_mut().zip(BEAM_INSETS) {
            let x = sx - inset * px * sx - sx / 2.0;
            let from = on_robot(
                at,
                Pose {
                    x,
                    y: gap_half,
                    a: -std::f64::consts::FRAC_PI_2,
                },
            );
            *beam = self
                .grippable_along(from, open * (sy - 2.0 * sy * py))
                .is_some();
        }
        // The contacts run along each paddle's inner face, from its root to its tip.
        let root = (1.0 - px) * sx - sx / 2.0;
        let contact = [gap_half, -gap_half]
            .into_iter()
            .find_map(|y| self.grippable_along(on_robot(at, Pose { x: root, y, a: 0.0 }), px * sx));
        let state = &mut self.robots[robot].grippers[gripper];
        state.beams = beams;
        if spec.autosnatch {
            state.command = if beams.iter().any(|b| *b) {
                GripperCommand::Close
            } else {
                GripperCommand::Open
            };
        }
        if let Some(hit) = contact
            && state.paddles == Paddles::Closing
            && state.gripped.is_none()
            && self.carried_by[hit].is_none()
        {
            state.gripped = Some(hit);
            let width = self.world.obstacles[hit].size[1];
            // Stage's limit, proportions and metres mixed as it mixes them.
            state.close_limit = (1.0 - width / (sy - py / 2.0)).max(0.0);
            self.carried_by[hit] = Some((robot, gripper));
        }
    }

    /// Puts every held obstacle where its gripper now is.
    pub(super) fn carry(&mut self) {
        for o in 0..self.carried_by.len() {
            if let Some((robot, gripper)) = self.carried_by[o] {
                self.world.obstacles[o].pose = self.gripper_pose(robot, gripper);
            }
        }
    }
}

//! Stage's `wander` controller: cruise ahead; when the ranger sees something close in the middle
//! third of its scan (or anything very close), slow down (stop, if very close) and turn away
//! from the nearer side, keeping that turn for a random 10 to 19 updates. Stage draws the
//! duration from `random()`; here it is a pure function of the seed, the step and the robot.

use super::{Command, Simulation};
use crate::world::Controller;

/// Forward speed while the way is clear, m/s (Stage's).
const CRUISE_SPEED: f64 = 0.4;
/// Forward speed while turning away, m/s.
const AVOID_SPEED: f64 = 0.05;
/// Turn rate while turning away, rad/s.
const AVOID_TURN: f64 = 0.5;
/// Something nearer than this in the middle third of the scan is in the way, m.
const MIN_FRONT_DISTANCE: f64 = 1.0;
/// Anything nearer than this, anywhere in the scan, stops the robot, m.
const STOP_DISTANCE: f64 = 0.3;
/// A turn lasts this many updates and up to as many more.
const AVOID_DURATION: u32 = 10;
/// Tells the wander draws apart from the range noise drawn from the same seed.
const WANDER_STREAM: u64 = 0x5741_4e44_4552;

/// How a wandering robot is turning away.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WanderState {
    /// Updates left in the current turn.
    pub avoid_count: u32,
    /// +1 left, -1 right.
    pub turn: i8,
}

/// What the wander controller reads of a scan.
#[derive(Debug, Clone, Copy)]
struct Sight {
    /// Something nearer than [`MIN_FRONT_DISTANCE`] in the scan's middle third.
    obstruction: bool,
    /// Anything nearer than [`STOP_DISTANCE`].
    stop: bool,
    /// The nearest reading of each half (the left one from past the middle beam).
    min_left: f64,
    min_right: f64,
}

impl Sight {
    /// What `scan` shows; `None` for a scan of no beams. Read on the thread that cast the scan.
    fn of(scan: &[f64]) -> Option<Sight> {
        let n = scan.len();
        if n == 0 {
            return None;
        }
        let mut sight = Sight {
            obstruction: false,
            stop: false,
            min_left: f64::INFINITY,
            min_right: f64::INFINITY,
        };
        for (i, &range) in scan.iter().enumerate() {
            if i > n / 3 && i < n - n / 3 && range < MIN_FRONT_DISTANCE {
                sight.obstruction = true;
            }
            if range < STOP_DISTANCE {
                sight.stop = true;
            }
            if i > n / 2 {
                sight.min_left = sight.min_left.min(range);
            } else {
                sight.min_right = sight.min_right.min(range);
            }
        }
        Some(sight)
    }
}

impl Simulation {
    /// Every wandering robot's next command, each from its ranger's scan of the world as the
    /// step found it (the scans cast on the simulation's threads).
    pub(super) fn wander_all(&mut self) {
        let wanderers: Vec<(usize, usize)> = (0..self.robots.len())
            .filter_map(|i| match self.world.robots[i].controller {
                Some(Controller::Wander { ranger }) => Some((i, ranger)),
                _ => None,
            })
            .collect();
        if wanderers.is_empty() {
            return;
        }
        let sights = self.scans_of(&wanderers, Sight::of);
        for (&(robot, _), sight) in wanderers.iter().zip(sights) {
            if let Some(sight) = sight {
                self.wander(robot, sight);
            }
        }
    }

    /// Robot `robot`'s next command from what its ranger saw, as Stage's wander decides it.
    fn wander(&mut self, robot: usize, sight: Sight) {
        let Sight {
            obstruction,
            stop,
            min_left,
            min_right,
        } = sight;
        let steps = self.steps;
        let noise = self.noise;
        let state = &mut self.robots[robot].wander;
        let command = if obstruction || stop || state.avoid_count > 0 {
            if state.avoid_count < 1 {
                let draw = noise.uniform(&[WANDER_STREAM, steps, robot as u64]);
                state.avoid_count = AVOID_DURATION + (draw * f64::from(AVOID_DURATION)) as u32;
                state.turn = if min_left < min_right { -1 } else { 1 };
            }
            state.avoid_count -= 1;
            Command::Velocity {
                vx: if stop { 0.0 } else { AVOID_SPEED },
                vy: 0.0,
                va: f64::from(state.turn) * AVOID_TURN,
            }
        } else {
            state.avoid_count = 0;
            Command::Velocity {
                vx: CRUISE_SPEED,
                vy: 0.0,
                va: 0.0,
            }
        };
        self.robots[robot].command = command;
    }
}

//! People walking: each step a person moves towards their next way-point at their speed, and
//! their two legs — obstacles the rangers see — swing back and forth about the body as a
//! walker's do, one ahead while the other is behind, so that a laser sees two leg-sized
//! blobs that part and meet. Deterministic: wander way-points come from the world's seed.

use super::Simulation;
use crate::world::{Pose, STANCE_WIDTH, Walk};

/// Distance walked in one full gait cycle (two steps), m.
const STRIDE: f64 = 1.0;
/// How far a leg swings ahead of (and behind) the body, m.
const SWING: f64 = 0.15;
/// A way-point this near is reached, m.
const REACHED: f64 = 0.05;
/// Tries at a wander way-point that is not in a wall, before standing still.
const WANDER_TRIES: u64 = 8;
/// Tells the wander draws apart from the other draws of the same seed.
const WALK_STREAM: u64 = 0x5045_5253_4f4e;

/// Where a person is and where they are going.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WalkerState {
    pub x: f64,
    pub y: f64,
    pub heading: f64,
    /// Way-points reached so far (indexes the path; seeds the wander draws).
    pub reached: u64,
    /// Distance walked, m: the gait's phase.
    pub walked: f64,
}

impl WalkerState {
    pub fn at(start: Pose) -> WalkerState {
        WalkerState {
            x: start.x,
            y: start.y,
            heading: start.a,
            ..WalkerState::default()
        }
    }
}

impl Simulation {
    /// Where person `i` is heading now, if anywhere.
    fn waypoint(&self, i: usize) -> Option<(f64, f64)> {
        let spec = &self.world.people[i];
        let reached = self.walkers[i].reached;
        match &spec.walk {
            Walk::Stand => None,
            Walk::Path(points) if points.is_empty() => None,
            Walk::Path(points) => Some(points[(reached % points.len() as u64) as usize]),
            Walk::Wander(radius) => (0..WANDER_TRIES).find_map(|attempt| {
                let draw = |axis| {
                    self.noise
                        .uniform(&[WALK_STREAM, i as u64, reached, attempt, axis])
                };
                let (angle, spread) = (draw(0) * std::f64::consts::TAU, draw(1).sqrt() * radius);
                let (x, y) = (
                    spec.start.x + spread * angle.cos(),
                    spec.start.y + spread * angle.sin(),
                );
                let free = self
                    .world
                    .floor
                    .as_ref()
                    .is_none_or(|f| !f.occupied_at(x, y));
                free.then_some((x, y))
            }),
        }
    }

    /// Moves every person one step and puts their legs where the gait has them.
    pub(super) fn walk_people(&mut self) {
        let dt = self.world.interval;
        for i in 0..self.walkers.len() {
            if let Some((tx, ty)) = self.waypoint(i) {
                let speed = self.world.people[i].speed;
                let w = &mut self.walkers[i];
                let (dx, dy) = (tx - w.x, ty - w.y);
                let gap = dx.hypot(dy);
                if gap <= REACHED.max(speed * dt) {
                    w.walked += gap;
                    (w.x, w.y) = (tx, ty);
                    w.reached += 1;
                } else {
                    let stride = speed * dt;
                    w.heading = dy.atan2(dx);
                    w.x += dx / gap * stride;
                    w.y += dy / gap * stride;
                    w.walked += stride;
                }
            }
            self.place_legs(i);
        }
    }

    /// Puts person `i`'s legs about their body as the gait's phase has them.
    pub(super) fn place_legs(&mut self, i: usize) {
        let w = &self.walkers[i];
        let phase = w.walked / STRIDE * std::f64::consts::TAU;
        let (s, c) = w.heading.sin_cos();
        let legs = self.world.people[i].legs;
        for (leg, side) in legs.into_iter().zip([1.0, -1.0]) {
            let ahead = side * SWING * phase.sin();
            let across = side * STANCE_WIDTH / 2.0;
            self.world.obstacles[leg].pose = Pose {
                x: w.x + c * ahead - s * across,
                y: w.y + s * ahead + c * across,
                a: w.heading,
            };
        }
    }
}

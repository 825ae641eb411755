//! What a robot's position2d reports as its pose: the true pose (`localization "gps"`), or
//! odometry (`"odom"`) integrated each step from the velocity the robot was told to drive at,
//! within its bounds, each step's motion scaled by `1 + error` as Stage 4.3 integrates it. The
//! odometry counts what the wheels were told, not where the robot went: a robot stalled
//! against a wall still reports moving, as Stage's does. Moving a robot by hand
//! (`simulation:0`) does not touch its odometry; `SET_ODOM` / `RESET_ODOM` set it.
//!
//! The error factors of a robot whose model gives no `odom_error` are drawn from the world's
//! seed (not a clock, as Stage's are), so that a seeded or lockstep run is the same every time.

use super::{Noise, Simulation};
use crate::world::{DEFAULT_ODOM_ERROR_SPAN, Localization, LocalizationSpec, Pose};

/// Keeps the odometry's draws apart from the noise's and the wander controller's.
const ODOMETRY_DRAW: u64 = 0x0D0_E550;

/// Robot `robot`'s odometry error factors (x, y, turn): its model's, else drawn from the seed
/// uniformly within Stage's default spans (each ± half its span).
pub fn odometry_error(spec: &LocalizationSpec, noise: &Noise, robot: usize) -> [f64; 3] {
    if let Some(error) = spec.odom_error {
        return error;
    }
    let mut error = [0.0; 3];
    for (axis, (e, span)) in error.iter_mut().zip(DEFAULT_ODOM_ERROR_SPAN).enumerate() {
        let u = noise.uniform(&[ODOMETRY_DRAW, robot as u64, axis as u64]);
        *e = u * span - span / 2.0;
    }
    error
}

/// `estimate` moved by one step of `dt` seconds at `(vx, vy, va)` (robot frame) with the error
/// factors `error`, as Stage 4.3 integrates it: the heading first, then the step along the new
/// heading. Stage's sideways term enters with its sign turned (a left step reads as a right
/// one); only omnidirectional robots step sideways, and they read as Stage's do.
pub fn integrate(estimate: Pose, (vx, vy, va): (f64, f64, f64), dt: f64, error: [f64; 3]) -> Pose {
    let a = super::wrap(estimate.a + va * dt * (1.0 + error[2]));
    let (s, c) = a.sin_cos();
    let dx = vx * dt * (1.0 + error[0]);
    let dy = vy * dt * (1.0 + error[1]);
    Pose {
        x: estimate.x + dx * c + dy * s,
        y: estimate.y - (dy * c - dx * s),
        a,
    }
}

impl Simulation {
    /// The pose robot `i`'s position2d reports: the true pose with gps, the odometry's with odom.
    /// (Stage reports a gps robot where it stood before the step's motion, one step behind;
    /// player-sim reports where it stands.)
    pub fn reported_pose(&self, i: usize) -> Pose {
        match self.world.robots[i].localization.mode {
            Localization::Gps => self.robots[i].pose,
            Localization::Odom => self.robots[i].estimate,
        }
    }

    /// Sets robot `i`'s odometry (Player's `SET_ODOM`; `RESET_ODOM` sets it to zero). With gps
    /// the report stays the true pose, as in Stage, which overwrites it with the next step.
    pub fn set_odometry(&mut self, i: usize, pose: Pose) {
        self.robots[i].estimate = pose;
    }

    /// Advances robot `i`'s estimate by this step, before it moves at `velocity`: odometry
    /// integrates the velocity; with gps Stage keeps the pose the robot stands at before it
    /// moves, which its position controller steers from the next step (one step behind).
    pub(super) fn integrate_odometry(&mut self, i: usize, velocity: (f64, f64, f64), dt: f64) {
        let spec = &self.world.robots[i].localization;
        if spec.mode == Localization::Gps {
            self.robots[i].estimate = self.robots[i].pose;
            return;
        }
        let error = odometry_error(spec, &self.noise, i);
        let robot = &mut self.robots[i];
        robot.estimate = integrate(robot.estimate, velocity, dt, error);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_straight_drive_reads_long_by_its_error_and_a_turn_by_its_own() {
        let step = integrate(Pose::default(), (1.0, 0.0, 0.0), 0.1, [0.1, 0.0, 0.0]);
        assert!(
            (step.x - 0.11).abs() < 1e-12 && step.y.abs() < 1e-12,
            "{step:?}"
        );
        let turn = integrate(Pose::default(), (0.0, 0.0, 1.0), 0.5, [0.0, 0.0, -0.2]);
        assert!((turn.a - 0.4).abs() < 1e-12, "{turn:?}");
        // Heading north, a step forward goes north.
        let north = Pose {
            a: std::f64::consts::FRAC_PI_2,
            ..Pose::default()
        };
        let up = integrate(north, (1.0, 0.0, 0.0), 1.0, [0.0; 3]);
        assert!(up.x.abs() < 1e-12 && (up.y - 1.0).abs() < 1e-12, "{up:?}");
        // Stage's sideways sign: heading east, a step to the left reads as one to the right.
        let side = integrate(Pose::default(), (0.0, 1.0, 0.0), 1.0, [0.0; 3]);
        assert!((side.y + 1.0).abs() < 1e-12, "{side:?}");
    }

    #[test]
    fn drawn_errors_stay_within_stages_spans_and_follow_the_seed() {
        let spec = LocalizationSpec {
            mode: Localization::Odom,
            ..LocalizationSpec::default()
        };
        let seeded = |seed| Noise {
            seed,
            range_sd: 0.0,
        };
        let errors: Vec<[f64; 3]> = (0..200)
            .map(|r| odometry_error(&spec, &seeded(5), r))
            .collect();
        for e in &errors {
            assert!(
                e[0].abs() <= 0.015 && e[1].abs() <= 0.015 && e[2].abs() <= 0.025,
                "{e:?}"
            );
        }
        assert!(errors.iter().any(|e| e[0] > 0.01) && errors.iter().any(|e| e[0] < -0.01));
        assert_ne!(errors[0], errors[1], "each robot its own");
        assert_eq!(errors[0], odometry_error(&spec, &seeded(5), 0));
        assert_ne!(errors[0], odometry_error(&spec, &seeded(6), 0));
        let given = LocalizationSpec {
            odom_error: Some([0.1, 0.2, 0.3]),
            ..spec
        };
        assert_eq!(odometry_error(&given, &seeded(5), 0), [0.1, 0.2, 0.3]);
    }
}

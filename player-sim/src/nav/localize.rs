//! A localizer that knows: the estimate is the robot's ground truth seen through a fixed frame
//! offset, so a client meets the behaviour of Player's `amcl` (or `fakelocalize`) without a
//! particle filter.
//!
//! * `amcl`: one hypothesis of weight 1 with a small constant covariance (a converged filter's
//!   order of magnitude, not a computed one). The estimate starts at `init_pose` and a set-pose
//!   request re-initialises it there: from then on it follows the robot's motion, as amcl's
//!   belief would if its laser could not correct it. Hypotheses go out when amcl's filter
//!   would update (first use, set pose, and motion past `update_thresh`); the particles
//!   request gets a small deterministic cloud around the estimate.
//! * `fakelocalize`: the ground truth itself every step, zero covariance, weight 1e6, and a
//!   set pose moves the robot in the simulation, as Player's driver does.

use std::f64::consts::PI;

use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::localize::{
    LocalizeData, LocalizeHypothesis, LocalizeParticle, LocalizeParticles, PoseCovariance, cov,
};

use super::frames::{relative, to_pose2d};
use crate::sim::on_robot;
use crate::world::Pose;

/// amcl's default `update_thresh`: 0.2 m, 30°.
pub const DEFAULT_UPDATE_DISTANCE: f64 = 0.2;
pub const DEFAULT_UPDATE_ANGLE: f64 = PI / 6.0;
/// amcl's default `pf_min_samples`: the size of the cloud a particles request gets.
pub const DEFAULT_PARTICLES: usize = 100;
/// The standard deviations of the reported covariance: a few centimetres and about a degree,
/// what amcl reports once converged in the captures.
const POSITION_SD: f64 = 0.02;
const HEADING_SD: f64 = 0.01;
/// `fakelocalize` weighs its single hypothesis so.
const FAKE_WEIGHT: f64 = 1e6;
/// Turns between successive particles of the cloud: the golden angle spreads them evenly.
const GOLDEN_ANGLE: f64 = 2.399_963_229_728_653;

/// Which of Player's localization drivers is imitated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LocalizerKind {
    Amcl,
    Fake,
}

/// What a `.cfg` asks of a localization driver.
#[derive(Debug, Clone, PartialEq)]
pub struct LocalizeSettings {
    pub kind: LocalizerKind,
    /// The robot whose odometry (or simulation model) the driver reads.
    pub robot: usize,
    /// amcl's `init_pose`, metres and radians.
    pub init_pose: Option<Pose>,
    /// amcl's `update_thresh`: distance (m) and angle (rad) of motion between filter updates.
    pub update_distance: f64,
    pub update_angle: f64,
    /// amcl's `pf_min_samples`.
    pub particles: usize,
}

/// A localizer's running state.
#[derive(Debug, Clone, PartialEq)]
pub struct Localizer {
    pub settings: LocalizeSettings,
    /// The estimate is `offset ∘ truth`.
    offset: Pose,
    /// Where the robot truly was at the last filter update; `None` until the first.
    updated_at: Option<Pose>,
    /// An update is due at the next step (first use, set pose, a new subscriber).
    due: bool,
    /// The filter updated during the last step: its hypotheses go out.
    pub updated: bool,
}

impl Localizer {
    pub fn new(settings: LocalizeSettings, truth: Pose) -> Localizer {
        let offset = match (settings.kind, settings.init_pose) {
            (LocalizerKind::Amcl, Some(init)) => offset_for(init, truth),
            _ => Pose::default(),
        };
        Localizer {
            settings,
            offset,
            updated_at: None,
            due: true,
            updated: false,
        }
    }

    /// The estimated pose of the robot that truly stands at `truth`.
    pub fn estimate(&self, truth: Pose) -> Pose {
        if self.offset == Pose::default() {
            // The truth itself, without the rounding of a composition.
            truth
        } else {
            on_robot(self.offset, truth)
        }
    }

    /// Asks for an update at the next step, as amcl's setup publishes one to a new subscriber.
    pub fn refresh(&mut self) {
        self.due = true;
    }

    /// Re-initialises amcl's estimate at `mean` (the robot truly at `truth`); `fakelocalize`
    /// moves the robot instead, which the caller does.
    pub fn set_pose(&mut self, mean: Pose, truth: Pose) {
        if self.settings.kind == LocalizerKind::Amcl {
            self.offset = offset_for(mean, truth);
        }
        self.due = true;
    }

    /// One simulation step with the robot at `truth`: does the filter update?
    pub fn step(&mut self, truth: Pose) {
        let moved = self.updated_at.is_some_and(|at| {
            let d = relative(at, truth);
            d.x.abs() > self.settings.update_distance
                || d.y.abs() > self.settings.update_distance
                || d.a.abs() > self.settings.update_angle
        });
        self.updated = self.due || moved || self.settings.kind == LocalizerKind::Fake;
        if self.updated {
            self.due = false;
            self.updated_at = Some(truth);
        }
    }

    /// The hypotheses, as the driver sends them; `time` is `fakelocalize`'s pending time (the
    /// simulation's clock), amcl sends 0.
    pub fn hypotheses(&self, truth: Pose, time: f64) -> LocalizeData {
        let mean = to_pose2d(self.estimate(truth));
        let (cov, alpha, pending_time) = match self.settings.kind {
            LocalizerKind::Amcl => (small_covariance(), 1.0, 0.0),
            LocalizerKind::Fake => (PoseCovariance::default(), FAKE_WEIGHT, time),
        };
        LocalizeData {
            pending_count: 0,
            pending_time,
            hypoths: vec![LocalizeHypothesis { mean, cov, alpha }],
        }
    }

    /// The answer to a particles request: amcl's cloud (its mean without a heading, as amcl
    /// fills it), or `fakelocalize`'s one particle at the truth.
    pub fn particles(&self, truth: Pose) -> LocalizeParticles {
        let at = self.estimate(truth);
        if self.settings.kind == LocalizerKind::Fake {
            return LocalizeParticles {
                mean: to_pose2d(at),
                variance: 0.0,
                particles: vec![LocalizeParticle {
                    pose: to_pose2d(at),
                    alpha: 1.0,
                }],
            };
        }
        let n = self.settings.particles.max(1);
        let weight = 1.0 / n as f64;
        let particles: Vec<LocalizeParticle> = (0..n)
            .map(|k| {
                // A sunflower spiral over two standard deviations: even, and the same every time.
                let share = (k as f64 + 0.5) / n as f64;
                let r = 2.0 * POSITION_SD * share.sqrt();
                let turn = k as f64 * GOLDEN_ANGLE;
                LocalizeParticle {
                    pose: Pose2d::new(
                        at.x + r * turn.cos(),
                        at.y + r * turn.sin(),
                        at.a + HEADING_SD * (2.0 * share - 1.0),
                    ),
                    alpha: weight,
                }
            })
            .collect();
        let variance = particles
            .iter()
            .map(|p| (p.pose.px - at.x).powi(2) + (p.pose.py - at.y).powi(2))
            .sum::<f64>()
            * weight;
        LocalizeParticles {
            mean: Pose2d::new(at.x, at.y, 0.0),
            variance,
            particles,
        }
    }
}

/// The offset that makes the robot at `truth` appear at `estimate`.
fn offset_for(estimate: Pose, truth: Pose) -> Pose {
    let a = estimate.a - truth.a;
    let (s, c) = a.sin_cos();
    Pose {
        x: estimate.x - (c * truth.x - s * truth.y),
        y: estimate.y - (s * truth.x + c * truth.y),
        a,
    }
}

fn small_covariance() -> PoseCovariance {
    let mut c = PoseCovariance::default();
    c[cov::XX] = POSITION_SD * POSITION_SD;
    c[cov::YY] = POSITION_SD * POSITION_SD;
    c[cov::AA] = HEADING_SD * HEADING_SD;
    c
}

#[cfg(test)]
mod tests {
    use super::*;

    fn amcl() -> LocalizeSettings {
        LocalizeSettings {
            kind: LocalizerKind::Amcl,
            robot: 0,
            init_pose: None,
            update_distance: 0.2,
            update_angle: 15f64.to_radians(),
            particles: DEFAULT_PARTICLES,
        }
    }

    fn close(a: Pose, b: Pose) -> bool {
        (a.x - b.x).abs() < 1e-9 && (a.y - b.y).abs() < 1e-9 && (a.a - b.a).abs() < 1e-9
    }

    #[test]
    fn a_set_pose_moves_the_estimate_which_then_follows_the_robot() {
        let truth = Pose {
            x: 1.0,
            y: 2.0,
            a: 0.5,
        };
        let mut loc = Localizer::new(amcl(), truth);
        assert!(close(loc.estimate(truth), truth));
        let told = Pose {
            x: -3.0,
            y: 0.0,
            a: 2.0,
        };
        loc.set_pose(told, truth);
        assert!(close(loc.estimate(truth), told));
        // One metre ahead in the robot's own frame is one metre ahead of the estimate too.
        let ahead = on_robot(
            truth,
            Pose {
                x: 1.0,
                ..Pose::default()
            },
        );
        let expected = on_robot(
            told,
            Pose {
                x: 1.0,
                ..Pose::default()
            },
        );
        assert!(close(loc.estimate(ahead), expected));
    }

    #[test]
    fn updates_come_first_then_only_after_enough_motion() {
        let mut loc = Localizer::new(amcl(), Pose::default());
        let at = |x: f64, a: f64| Pose { x, y: 0.0, a };
        loc.step(at(0.0, 0.0));
        assert!(loc.updated);
        loc.step(at(0.1, 0.0));
        assert!(!loc.updated);
        loc.step(at(0.25, 0.0));
        assert!(loc.updated);
        loc.step(at(0.25, 0.2));
        assert!(!loc.updated);
        loc.step(at(0.25, 0.3));
        assert!(loc.updated);
        loc.refresh();
        loc.step(at(0.25, 0.3));
        assert!(loc.updated);
    }

    #[test]
    fn the_cloud_surrounds_the_estimate_with_weights_summing_to_one() {
        let loc = Localizer::new(amcl(), Pose::default());
        let truth = Pose {
            x: 2.0,
            y: -1.0,
            a: 1.0,
        };
        let cloud = loc.particles(truth);
        assert_eq!(cloud.particles.len(), DEFAULT_PARTICLES);
        let sum: f64 = cloud.particles.iter().map(|p| p.alpha).sum();
        assert!((sum - 1.0).abs() < 1e-9);
        assert!(cloud.particles.iter().all(|p| {
            (p.pose.px - 2.0).hypot(p.pose.py + 1.0) <= 2.0 * POSITION_SD + 1e-12
                && (p.pose.pa - 1.0).abs() <= HEADING_SD
        }));
        assert!(cloud.variance > 0.0 && cloud.variance < 4.0 * POSITION_SD * POSITION_SD);
        assert_eq!(
            (cloud.mean.px, cloud.mean.py, cloud.mean.pa),
            (2.0, -1.0, 0.0)
        );
    }

    #[test]
    fn fakelocalize_is_the_truth_every_step_with_no_uncertainty() {
        let settings = LocalizeSettings {
            kind: LocalizerKind::Fake,
            init_pose: Some(Pose {
                x: 9.0,
                ..Pose::default()
            }),
            ..amcl()
        };
        let truth = Pose {
            x: 1.0,
            y: 1.0,
            a: 0.3,
        };
        let mut loc = Localizer::new(settings, truth);
        for _ in 0..3 {
            loc.step(truth);
            assert!(loc.updated);
        }
        let data = loc.hypotheses(truth, 4.5);
        let h = data.best().unwrap();
        assert_eq!((h.mean.px, h.mean.py, h.mean.pa), (1.0, 1.0, 0.3));
        assert_eq!(
            (h.cov, h.alpha, data.pending_time),
            ([0.0; 6], FAKE_WEIGHT, 4.5)
        );
        assert_eq!(loc.particles(truth).particles.len(), 1);
    }
}

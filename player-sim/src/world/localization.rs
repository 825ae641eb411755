//! How a robot's position2d says where it is, as Stage 4.3 reads it from a `position` model:
//! `localization "gps"` (the default) reports the true pose in the world; `localization
//! "odom"` reports a pose integrated from the commanded velocity, each step's motion scaled by
//! `1 + odom_error` (so it drifts), in a frame whose origin is `localization_origin` (the
//! robot's start pose unless set, so that odometry starts at zero).
//!
//! Stage's facts kept here (checked against its source): `localization_origin` is used by
//! odometry only (with gps Stage 4.3 reports the world pose whatever the origin); both
//! `localization_origin` and `odom_error` are read as a pose, four numbers `[x y z a]`, so
//! odom_error's fourth number, the turn's error factor, is read as degrees and turned into
//! radians (`odom_error [0.03 0.03 0 0.05]` is a 0.087 % turn error, not 5 %); without
//! `odom_error` each robot's factors are drawn uniformly within ±1.5 % (x, y) and ±2.5 %
//! (turn): here from the world's seed, so a run is reproduced by its seed.

use super::Pose;
use super::models::Model;
use super::properties::{err, numbers, string};
use crate::worldfile::{Property, WorldFileError};

/// Where position2d's reported pose comes from (Stage's `localization`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Localization {
    /// The true pose in the world.
    #[default]
    Gps,
    /// Integrated from the commanded velocities, with the odometry's error.
    Odom,
}

/// A robot's localization as its model sets it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LocalizationSpec {
    pub mode: Localization,
    /// The odometry frame's origin in the world (`localization_origin`); `None`: where the
    /// robot starts.
    pub origin: Option<Pose>,
    /// Error factors of x, y and turn (`odom_error`, the turn's in radians as Stage reads
    /// it); `None`: drawn from the world's seed as Stage draws them.
    pub odom_error: Option<[f64; 3]>,
}

/// Stage's widest default odometry error factors, x, y and turn (each drawn within ± half).
pub const DEFAULT_ODOM_ERROR_SPAN: [f64; 3] = [0.03, 0.03, 0.05];

impl LocalizationSpec {
    /// The model's localization properties; a mode Stage does not know is refused with where
    /// it is written (Stage says so and goes on with gps: a typo here would silently give a
    /// student perfect odometry).
    pub(super) fn of(model: &Model) -> Result<LocalizationSpec, WorldFileError> {
        let mode = match model.get("localization") {
            None => Localization::Gps,
            Some(p) => match string(p)? {
                "gps" => Localization::Gps,
                "odom" => Localization::Odom,
                other => {
                    return Err(err(
                        &p.pos,
                        format!("localization {other:?}: Stage's are \"gps\" and \"odom\""),
                    ));
                }
            },
        };
        let origin = model
            .get("localization_origin")
            .map(|p| stage_pose(p).map(|[x, y, a]| Pose { x, y, a }))
            .transpose()?;
        let odom_error = model.get("odom_error").map(stage_pose).transpose()?;
        if let Some(p) = model.get("odom_error")
            && odom_error.is_some_and(|e| e.iter().any(|f| !f.is_finite()))
        {
            return Err(err(&p.pos, "odom_error must be finite numbers"));
        }
        Ok(LocalizationSpec {
            mode,
            origin,
            odom_error,
        })
    }

    /// The odometry's reading where the robot stands at `start`: `start` in the origin's frame.
    pub fn odometry_start(&self, start: Pose) -> Pose {
        let origin = self.origin.unwrap_or(start);
        let (s, c) = origin.a.sin_cos();
        let (dx, dy) = (start.x - origin.x, start.y - origin.y);
        Pose {
            x: dx * c + dy * s,
            y: dy * c - dx * s,
            a: (start.a - origin.a).sin().atan2((start.a - origin.a).cos()),
        }
    }
}

/// `[x y z a]` as Stage reads a pose-typed property: four numbers, metres and degrees; x, y
/// and a (radians) kept.
fn stage_pose(p: &Property) -> Result<[f64; 3], WorldFileError> {
    let n = numbers(Some(p), 4, &p.pos)?;
    Ok([n[0], n[1], n[3].to_radians()])
}

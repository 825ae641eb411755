//! A robot's `velocity_bounds` as Stage reads them: `[xmin xmax ymin ymax zmin zmax amin amax]`,
//! metres a second and degrees a second; a commanded velocity is held within them. Stage bounds
//! every robot, by default to 1 m/s each way and 90 degrees a second.

use super::models::Model;
use super::properties::{err, numbers};
use crate::worldfile::WorldFileError;

/// Least and most velocity along x, y (m/s) and about z (rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VelocityBounds {
    pub x: (f64, f64),
    pub y: (f64, f64),
    pub a: (f64, f64),
}

impl Default for VelocityBounds {
    /// Stage's, for a model that sets none.
    fn default() -> Self {
        let turn = 90f64.to_radians();
        VelocityBounds {
            x: (-1.0, 1.0),
            y: (-1.0, 1.0),
            a: (-turn, turn),
        }
    }
}

impl VelocityBounds {
    /// The model's `velocity_bounds`, or Stage's default.
    pub(super) fn of(model: &Model) -> Result<VelocityBounds, WorldFileError> {
        let Some(p) = model.get("velocity_bounds") else {
            return Ok(VelocityBounds::default());
        };
        let n = numbers(Some(p), 8, &p.pos)?;
        let pair = |i: usize| (n[i], n[i + 1]);
        let bounds = VelocityBounds {
            x: pair(0),
            y: pair(2),
            a: (n[6].to_radians(), n[7].to_radians()),
        };
        for (lo, hi) in [bounds.x, bounds.y, bounds.a] {
            if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
                return Err(err(
                    &p.pos,
                    "velocity_bounds must be finite, each least no more than its most",
                ));
            }
        }
        Ok(bounds)
    }

    /// `(vx, vy, va)` held within the bounds.
    pub fn clamp(&self, (vx, vy, va): (f64, f64, f64)) -> (f64, f64, f64) {
        (
            vx.clamp(self.x.0, self.x.1),
            vy.clamp(self.y.0, self.y.1),
            va.clamp(self.a.0, self.a.1),
        )
    }
}

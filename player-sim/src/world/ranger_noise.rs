//! A ranger sensor's `noise [range_const range_prop angular]`, as Stage 4.3 reads it (its only
//! sensor noise; none unless a sensor sets it): a Gaussian of variance `range_const` (m²) and
//! a uniform share of the range within ±`range_prop` added to a beam that hit something, and
//! the beam's direction turned by up to ±`angular`/2 times its spacing — `angular` read as an
//! angle in degrees and used in radians, as Stage does (its 0.5 turns a beam by a few
//! hundredths of a millidegree).

use super::properties::{err, numbers};
use crate::worldfile::{Block, WorldFileError};

/// A sensor's range and bearing noise (all zero: exact readings).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RangerNoise {
    /// Variance of the Gaussian added to a range, m².
    pub range_variance: f64,
    /// The most a range is off by, as a share of itself (uniform within ±).
    pub range_share: f64,
    /// Radians; a beam turns by up to ± half this times the beams' spacing.
    pub angular: f64,
}

impl RangerNoise {
    /// Whether any of it is set.
    pub fn is_none(&self) -> bool {
        *self == RangerNoise::default()
    }

    /// The `noise` of a ranger's `sensor()`, if it has one.
    pub(super) fn of(sensor: &Block) -> Result<RangerNoise, WorldFileError> {
        let Some(p) = sensor.get("noise") else {
            return Ok(RangerNoise::default());
        };
        let n = numbers(Some(p), 3, &p.pos)?;
        let noise = RangerNoise {
            range_variance: n[0],
            range_share: n[1],
            angular: n[2].to_radians(),
        };
        if !(noise.range_variance >= 0.0
            && noise.range_variance.is_finite()
            && noise.range_share.is_finite()
            && noise.angular.is_finite())
        {
            return Err(err(
                &p.pos,
                "noise [range_const range_prop angular] must be finite, range_const (a variance) \
                 not negative",
            ));
        }
        Ok(noise)
    }
}

//! The half-plane a scan's beams point into. A laser's fan spans half a turn, so half of the
//! bodies within its range stand behind it; each was placed in the scan's list, given its
//! bearing and half-width (`beams.rs`) and found in no beam's direction. A body whose bounding
//! circle lies wholly behind the fan's half-plane is left out of the list at once: no beam
//! would have listed it, so the scan is the same.

use std::f64::consts::FRAC_PI_2;

use super::beams::Fan;
use super::quick_angles::ANGLE_ERROR;

/// Fans reaching more than this beyond a half-turn each side are not told apart from a circle.
const MOST_LEAN: f64 = 0.5;

/// Where a fan's beams point from `at`: the fan's middle direction, and how far (as a sine) its
/// listing reaches past the half-plane square to it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Facing {
    at: (f64, f64),
    towards: (f64, f64),
    lean: f64,
}

impl Facing {
    /// The half-plane of `fan`'s beams from `at`, as wide as its lists reach (two beams past
    /// either end, and the bearings' error); `None` for a fan spread over more than a half-turn
    /// and a little, or not spread at all, whose lists may take in anything.
    pub(super) fn of(fan: Fan, at: (f64, f64)) -> Option<Facing> {
        if !(fan.step > 1e-9 && fan.count >= 2 && fan.first.is_finite()) {
            return None;
        }
        let half_span = (fan.count - 1) as f64 * fan.step / 2.0;
        let beyond = half_span + 2.0 * fan.step + 4.0 * ANGLE_ERROR - FRAC_PI_2;
        if beyond.is_nan() || beyond >= MOST_LEAN {
            return None;
        }
        let (sin, cos) = (fan.first + half_span).sin_cos();
        Some(Facing {
            at,
            towards: (cos, sin),
            lean: beyond.max(0.0).sin(),
        })
    }

    /// May any of the fan's lists take in the circle about `(x, y)` of `radius`? No where the
    /// whole circle lies behind the half-plane, leaned back by `lean` of its farthest point's
    /// distance (bounded by the sum of the offsets, which only leans it further).
    #[inline]
    pub(super) fn may_see(&self, (x, y): (f64, f64), radius: f64) -> bool {
        let (ex, ey) = (x - self.at.0, y - self.at.1);
        let ahead = ex * self.towards.0 + ey * self.towards.1;
        // NaN (a body placed nowhere) is not behind: the lists judge it.
        let behind = ahead + radius + self.lean * (ex.abs() + ey.abs() + radius) < 0.0;
        !behind
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::beams::beams_towards;
    use crate::sim::test_randoms::randoms;
    use std::f64::consts::{PI, TAU};

    /// A circle the half-plane leaves out is listed by none of the fan's beams, whatever the
    /// fan: lasers of 180 and 240 degrees, narrow fans, any heading.
    #[test]
    fn a_circle_left_out_is_in_no_beams_direction() {
        let mut next = randoms(0xfac1);
        let (mut left_out, mut kept) = (0, 0);
        for k in 0..400 {
            let (count, span) = [(180, PI), (181, PI), (361, PI), (60, 0.5), (667, 4.2)][k % 5];
            let step = span / (count - 1) as f64;
            let fan = Fan {
                first: TAU * next() - PI,
                step,
                count,
            };
            let at = (10.0 * next() - 5.0, 10.0 * next() - 5.0);
            let Some(facing) = Facing::of(fan, at) else {
                assert!(span > PI, "{span}");
                continue;
            };
            for _ in 0..200 {
                let (x, y) = (at.0 + 16.0 * next() - 8.0, at.1 + 16.0 * next() - 8.0);
                let radius = 0.02 + next() * next() * 2.0;
                if facing.may_see((x, y), radius) {
                    kept += 1;
                    continue;
                }
                left_out += 1;
                let lists = beams_towards(fan, x - at.0, y - at.1, radius);
                assert!(
                    lists.iter().all(|&(lo, hi)| lo == hi),
                    "{k}: ({x}, {y}) r {radius} {lists:?}"
                );
            }
        }
        assert!(left_out > 10_000 && kept > 10_000, "{left_out} {kept}");
    }
}

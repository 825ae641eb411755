//! The bearing and the angular half-width of a circle seen from a sensor, to within
//! [`ANGLE_ERROR`], without the maths library's calls. A scan lists its boxes and its walls'
//! parts by the beams pointing at their bounding circles (`beams.rs`, `wall_free.rs`): an
//! `atan2` and an `asin` for every circle of every scan, a few per cent of the cave's run in
//! calls alone. The lists are widened by the error, so they hold every beam they held before
//! (the callers then test each box or part exactly).

use std::f64::consts::{FRAC_PI_2, PI};

/// The most either angle here differs from the exact one (radians): the arctangent's
/// polynomial is within 1e-5 of it on [0, 1] (Abramowitz and Stegun 4.4.47), and the rest is
/// rounding; a tenth of a milliradian leaves room for both.
pub(super) const ANGLE_ERROR: f64 = 1e-4;

/// `atan(z)` for `z` in [0, 1], within 1e-5.
#[inline]
fn atan_unit(z: f64) -> f64 {
    let z2 = z * z;
    z * (0.999_866 + z2 * (-0.330_299_5 + z2 * (0.180_141 + z2 * (-0.085_133 + z2 * 0.020_835_1))))
}

/// `y.atan2(x)` within [`ANGLE_ERROR`] (NaN where either is NaN, or both are infinite).
#[inline]
pub(super) fn atan2(y: f64, x: f64) -> f64 {
    let (ax, ay) = (x.abs(), y.abs());
    let steep = ay > ax;
    let (num, den) = if steep { (ax, ay) } else { (ay, ax) };
    if den == 0.0 {
        return y.atan2(x);
    }
    let a = atan_unit(num / den);
    let a = if steep { FRAC_PI_2 - a } else { a };
    let a = if x < 0.0 { PI - a } else { a };
    if y < 0.0 { -a } else { a }
}

/// `v.asin()` for `v` in [0, 1), within [`ANGLE_ERROR`].
#[inline]
pub(super) fn asin(v: f64) -> f64 {
    atan2(v, (1.0 - v * v).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::test_randoms::randoms;

    #[test]
    fn both_are_within_their_error_of_the_exact_angles() {
        let mut next = randoms(0xa7a2);
        let mut worst: f64 = 0.0;
        for k in 0..200_000 {
            let scale = [1e-3, 1.0, 30.0, 1e6][k % 4];
            let (x, y) = (scale * (2.0 * next() - 1.0), scale * (2.0 * next() - 1.0));
            worst = worst.max((atan2(y, x) - y.atan2(x)).abs());
            let v = next();
            worst = worst.max((asin(v) - v.asin()).abs());
        }
        for (y, x) in [(0.0, 1.0), (1.0, 0.0), (0.0, -1.0), (-1.0, 0.0), (1.0, 1.0)] {
            worst = worst.max((atan2(y, x) - f64::atan2(y, x)).abs());
        }
        assert!(worst < ANGLE_ERROR / 5.0, "{worst}");
        assert!(atan2(f64::NAN, 1.0).is_nan() && atan2(1.0, f64::NAN).is_nan());
        assert_eq!(atan2(0.0, 0.0), 0.0);
    }
}

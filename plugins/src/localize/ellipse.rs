//! How sure a localizer is of where the robot is, as a shape a person reads at a glance: the
//! 2-D position covariance turned into the ellipse that holds the true position with 95 %
//! probability. The closed-form eigen decomposition of a symmetric 2×2 matrix is used (no
//! linear-algebra crate for one matrix), and kept here so it is tested on its own.

use glam::Vec2;
use player_proto::interfaces::localize::{PoseCovariance, cov};

/// The χ² value with two degrees of freedom below which 95 % of a 2-D Gaussian lies: the
/// squared Mahalanobis radius of the 95 % ellipse (−2 ln 0.05).
pub const CHI2_2DOF_95: f64 = 5.991_464_547_107_979;

/// A covariance ellipse: the semi-axes along the principal directions, the major first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    /// Semi-axis along `angle`, m (the larger).
    pub major: f64,
    /// Semi-axis across `angle`, m.
    pub minor: f64,
    /// Direction of the major axis, rad from +x.
    pub angle: f64,
}

/// Eigenvalues (larger first) and the larger one's direction of the symmetric matrix
/// `[[xx, xy], [xy, yy]]`.
pub fn eigen_2x2(xx: f64, yy: f64, xy: f64) -> (f64, f64, f64) {
    let mean = (xx + yy) / 2.0;
    let spread = (((xx - yy) / 2.0).powi(2) + xy * xy).sqrt();
    // atan2 of twice the angle gives the major axis's direction for every sign of xy and of
    // xx − yy, including the isotropic case (any direction; 0 is returned).
    let angle = 0.5 * (2.0 * xy).atan2(xx - yy);
    (mean + spread, mean - spread, angle)
}

impl Ellipse {
    /// The 95 % ellipse of a pose covariance's x–y block. Negative variances (numerical noise
    /// from a filter) are read as zero, so that a bad estimate draws a point, not NaN.
    pub fn of_covariance(covariance: &PoseCovariance) -> Ellipse {
        let (large, small, angle) = eigen_2x2(
            covariance[cov::XX],
            covariance[cov::YY],
            covariance[cov::XY],
        );
        let radius = |variance: f64| (variance.max(0.0) * CHI2_2DOF_95).sqrt();
        Ellipse {
            major: radius(large),
            minor: radius(small),
            angle,
        }
    }

    /// `segments` points on the ellipse around `centre`, counter-clockwise from the major
    /// axis's end.
    pub fn outline(&self, centre: Vec2, segments: usize) -> Vec<Vec2> {
        let axis = Vec2::from_angle(self.angle as f32);
        let across = axis.perp();
        (0..segments)
            .map(|k| {
                let t = std::f32::consts::TAU * k as f32 / segments as f32;
                centre
                    + axis * (self.major as f32 * t.cos())
                    + across * (self.minor as f32 * t.sin())
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_4;

    fn covariance(xx: f64, yy: f64, xy: f64) -> PoseCovariance {
        let mut c = PoseCovariance::default();
        c[cov::XX] = xx;
        c[cov::YY] = yy;
        c[cov::XY] = xy;
        c[cov::AA] = 9.0;
        c
    }

    #[test]
    fn an_axis_aligned_covariance_has_its_variances_as_eigenvalues() {
        assert_eq!(eigen_2x2(4.0, 1.0, 0.0), (4.0, 1.0, 0.0));
        let (large, small, angle) = eigen_2x2(1.0, 4.0, 0.0);
        assert_eq!((large, small), (4.0, 1.0));
        assert!(
            (angle.abs() - std::f64::consts::FRAC_PI_2).abs() < 1e-12,
            "{angle}"
        );
    }

    #[test]
    fn a_correlated_covariance_turns_the_major_axis_and_its_eigenvectors_hold() {
        // [[2, 1], [1, 2]]: eigenvalues 3 and 1, the major along the diagonal.
        let (large, small, angle) = eigen_2x2(2.0, 2.0, 1.0);
        assert!((large - 3.0).abs() < 1e-12 && (small - 1.0).abs() < 1e-12);
        assert!((angle - FRAC_PI_4).abs() < 1e-12, "{angle}");
        // A v = λ v for the direction returned, with a lopsided, negatively correlated matrix.
        let (xx, yy, xy) = (3.0, 0.5, -0.8);
        let (large, _, angle) = eigen_2x2(xx, yy, xy);
        let v = (angle.cos(), angle.sin());
        let av = (xx * v.0 + xy * v.1, xy * v.0 + yy * v.1);
        assert!((av.0 - large * v.0).abs() < 1e-12 && (av.1 - large * v.1).abs() < 1e-12);
    }

    #[test]
    fn the_95_percent_ellipse_scales_the_standard_deviations() {
        let e = Ellipse::of_covariance(&covariance(0.25, 0.04, 0.0));
        let k = CHI2_2DOF_95.sqrt();
        assert!((e.major - 0.5 * k).abs() < 1e-12 && (e.minor - 0.2 * k).abs() < 1e-12);
        // The angular variance (9 rad²) plays no part in the position's ellipse.
        let points = e.outline(Vec2::new(1.0, 2.0), 4);
        assert!((points[0] - Vec2::new(1.0 + e.major as f32, 2.0)).length() < 1e-5);
        assert!((points[1] - Vec2::new(1.0, 2.0 + e.minor as f32)).length() < 1e-5);
    }

    #[test]
    fn noise_below_zero_draws_a_point_not_nan() {
        let e = Ellipse::of_covariance(&covariance(-1e-9, -1e-9, 0.0));
        assert_eq!((e.major, e.minor), (0.0, 0.0));
    }
}

//! The set-pose request a person's drag becomes: the pose given by hand, with a covariance
//! wide enough for the filter to settle from a hand-placed guess (a person's drag is good to
//! tens of centimetres and degrees, no better).

use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::localize::{LocalizeSetPose, PoseCovariance, cov};

/// How uncertain a pose given by hand is said to be.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HandPlacedSpread {
    /// Standard deviation of x and of y, m.
    pub position_sd: f64,
    /// Standard deviation of the heading, rad.
    pub heading_sd: f64,
}

/// The request body: `pose` with independent x, y and heading of the given spread.
pub fn set_pose_request(pose: Pose2d, spread: HandPlacedSpread) -> LocalizeSetPose {
    let mut covariance = PoseCovariance::default();
    covariance[cov::XX] = spread.position_sd * spread.position_sd;
    covariance[cov::YY] = spread.position_sd * spread.position_sd;
    covariance[cov::AA] = spread.heading_sd * spread.heading_sd;
    LocalizeSetPose {
        mean: pose,
        cov: covariance,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_variances_are_the_squared_spreads_and_nothing_correlates() {
        let spread = HandPlacedSpread {
            position_sd: 0.5,
            heading_sd: 0.2,
        };
        let request = set_pose_request(Pose2d::new(1.0, -2.0, 0.3), spread);
        assert_eq!(request.mean, Pose2d::new(1.0, -2.0, 0.3));
        assert_eq!(request.cov[cov::XX], 0.25);
        assert_eq!(request.cov[cov::YY], 0.25);
        assert!((request.cov[cov::AA] - 0.04).abs() < 1e-15);
        for off_diagonal in [cov::XY, cov::YA, cov::XA] {
            assert_eq!(request.cov[off_diagonal], 0.0);
        }
    }
}

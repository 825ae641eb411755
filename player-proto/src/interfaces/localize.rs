//! The `localize` interface (code 25): where a localizer (Player's `amcl`) believes the robot
//! is, in the map frame, as weighted Gaussian hypotheses.
//!
//! A pose's uncertainty travels as six doubles, the distinct entries of the symmetric 3×3
//! covariance in the order Player 3.1 fixes: xx, yy, aa, xy, ya, xa (m², rad², m·rad). Player
//! 3.0 and 2.x sent only the first three; [`PoseCovariance`] keeps the 3.1 layout.

use super::common::Pose2d;

/// Request subtype whose request body is empty (the ACK carries the particles).
pub const REQ_GET_PARTICLES: u8 = 2;

/// Doubles in a packed pose covariance: the distinct entries of a symmetric 3×3 matrix.
pub const COVARIANCE_LEN: usize = 6;

/// A pose covariance as it travels: `[xx, yy, aa, xy, ya, xa]`.
pub type PoseCovariance = [f64; COVARIANCE_LEN];

xdr_struct! {
    /// `player_localize_hypoth_t`: one Gaussian of the belief.
    #[derive(Copy)]
    pub struct LocalizeHypothesis {
        /// m, m, rad.
        pub mean: Pose2d,
        pub cov: PoseCovariance,
        /// Weight of this hypothesis in the mixture.
        pub alpha: f64,
    }
}

xdr_struct! {
    /// `player_localize_data_t`: the current belief.
    pub struct LocalizeData {
        /// Observations not yet processed.
        pub pending_count: u32,
        /// Time of the last processed observation, s.
        pub pending_time: f64,
        pub hypoths: Vec<LocalizeHypothesis>,
    }
}

xdr_struct! {
    /// `player_localize_set_pose_t`: re-initialise the belief around a pose (null reply).
    #[derive(Copy)]
    pub struct LocalizeSetPose {
        /// m, m, rad.
        pub mean: Pose2d,
        pub cov: PoseCovariance,
    }
}

xdr_struct! {
    /// `player_localize_particle_t`.
    #[derive(Copy)]
    pub struct LocalizeParticle {
        /// m, m, rad.
        pub pose: Pose2d,
        pub alpha: f64,
    }
}

xdr_struct! {
    /// `player_localize_get_particles_t`: (usually a subset of) a particle filter's samples.
    pub struct LocalizeParticles {
        /// The definition says mm and arc-seconds, a leftover: `amcl` fills m and rad (and
        /// leaves the yaw 0).
        pub mean: Pose2d,
        pub variance: f64,
        pub particles: Vec<LocalizeParticle>,
    }
}

interface_messages! {
    /// Messages of the `localize` interface.
    pub enum Localize for LOCALIZE {
        Data 1 as DATA_HYPOTHS => Hypotheses(LocalizeData),
        Request 1 as REQ_SET_POSE => SetPose(LocalizeSetPose),
        Request 2 as REQ_GET_PARTICLES => Particles(LocalizeParticles),
    }
}

/// Positions of the entries in a [`PoseCovariance`].
pub mod cov {
    pub const XX: usize = 0;
    pub const YY: usize = 1;
    pub const AA: usize = 2;
    pub const XY: usize = 3;
    pub const YA: usize = 4;
    pub const XA: usize = 5;
}

/// The full symmetric matrix (rows and columns x, y, yaw) of a packed covariance.
pub fn covariance_matrix(cov: &PoseCovariance) -> [[f64; 3]; 3] {
    [
        [cov[cov::XX], cov[cov::XY], cov[cov::XA]],
        [cov[cov::XY], cov[cov::YY], cov[cov::YA]],
        [cov[cov::XA], cov[cov::YA], cov[cov::AA]],
    ]
}

impl LocalizeData {
    /// The hypothesis with the largest weight: the pose a client acts on.
    pub fn best(&self) -> Option<&LocalizeHypothesis> {
        self.hypoths
            .iter()
            .max_by(|a, b| a.alpha.total_cmp(&b.alpha))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_packed_order_fills_a_symmetric_matrix() {
        let m = covariance_matrix(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        assert_eq!(m, [[1.0, 4.0, 6.0], [4.0, 2.0, 5.0], [6.0, 5.0, 3.0]]);
        for (i, row) in m.iter().enumerate() {
            for (j, v) in row.iter().enumerate() {
                assert_eq!(*v, m[j][i]);
            }
        }
    }

    #[test]
    fn the_heaviest_hypothesis_is_best() {
        let at = |x, alpha| LocalizeHypothesis {
            mean: Pose2d::new(x, 0.0, 0.0),
            alpha,
            ..Default::default()
        };
        let data = LocalizeData {
            hypoths: vec![at(1.0, 0.2), at(2.0, 0.7), at(3.0, 0.1)],
            ..Default::default()
        };
        assert_eq!(data.best().map(|h| h.mean.px), Some(2.0));
        assert!(LocalizeData::default().best().is_none());
    }
}

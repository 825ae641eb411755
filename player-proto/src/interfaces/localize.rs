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

/// What one hypothesis's weight says about the belief, whatever the driver meant by it.
///
/// Player leaves the weight's scale to the driver: amcl's weights are relative to one
/// another, fakelocalize sends a constant of its own (1e6), others may send nothing useful.
/// Only a share of the weights of one message is comparable across drivers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HypothesisShare {
    /// This hypothesis's part of the message's total weight, in `0.0..=1.0`.
    Fraction(f64),
    /// The message holds this hypothesis alone: a share of one says nothing.
    Sole,
    /// The weights cannot be compared: one of them is negative, NaN or infinite, or all are
    /// zero.
    Unknown,
}

/// How a share is read out — beside an estimate in the viewer, in `playerprint` — never a
/// percentage over 100.
impl std::fmt::Display for HypothesisShare {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            HypothesisShare::Fraction(share) if share > 0.0 && share < 0.005 => {
                f.write_str("< 1 %")
            }
            HypothesisShare::Fraction(share) => write!(f, "{:.0} %", share * 100.0),
            HypothesisShare::Sole => f.write_str("sole hypothesis"),
            HypothesisShare::Unknown => f.write_str("share unknown"),
        }
    }
}

/// A weight that can be compared with others: finite and not negative.
fn usable(weight: f64) -> bool {
    weight.is_finite() && weight >= 0.0
}

impl LocalizeData {
    /// The hypothesis with the largest usable weight (finite, not negative): the pose a client
    /// acts on. When no weight is usable, the first hypothesis.
    pub fn best(&self) -> Option<&LocalizeHypothesis> {
        self.hypoths
            .iter()
            .filter(|h| usable(h.alpha))
            .max_by(|a, b| a.alpha.total_cmp(&b.alpha))
            .or_else(|| self.hypoths.first())
    }

    /// `hypothesis`'s share of the weights of this message (see [`HypothesisShare`]).
    pub fn share_of(&self, hypothesis: &LocalizeHypothesis) -> HypothesisShare {
        if self.hypoths.len() == 1 {
            return HypothesisShare::Sole;
        }
        if !usable(hypothesis.alpha) || !self.hypoths.iter().all(|h| usable(h.alpha)) {
            return HypothesisShare::Unknown;
        }
        // Scaled by the heaviest first, so that weights near f64::MAX do not overflow the sum.
        let heaviest = self.hypoths.iter().map(|h| h.alpha).fold(0.0, f64::max);
        if heaviest == 0.0 {
            return HypothesisShare::Unknown;
        }
        let total: f64 = self.hypoths.iter().map(|h| h.alpha / heaviest).sum();
        HypothesisShare::Fraction((hypothesis.alpha / heaviest / total).clamp(0.0, 1.0))
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

    fn weighted(alphas: &[f64]) -> LocalizeData {
        LocalizeData {
            hypoths: alphas
                .iter()
                .enumerate()
                .map(|(i, &alpha)| LocalizeHypothesis {
                    mean: Pose2d::new(i as f64, 0.0, 0.0),
                    alpha,
                    ..Default::default()
                })
                .collect(),
            ..Default::default()
        }
    }

    fn shares(data: &LocalizeData) -> Vec<HypothesisShare> {
        data.hypoths.iter().map(|h| data.share_of(h)).collect()
    }

    #[test]
    fn shares_are_normalised_over_one_message() {
        use HypothesisShare::*;
        assert_eq!(
            shares(&weighted(&[3.0, 1.0])),
            [Fraction(0.75), Fraction(0.25)]
        );
        // fakelocalize's constant weight beside a weightless one.
        assert_eq!(
            shares(&weighted(&[1e6, 0.0])),
            [Fraction(1.0), Fraction(0.0)]
        );
        // Weights far outside 0..1 still share out to at most 1.
        let huge = weighted(&[f64::MAX, f64::MAX]);
        assert_eq!(
            shares(&huge),
            [Fraction(0.5), Fraction(0.5)],
            "a sum past f64::MAX"
        );
        assert_eq!(shares(&weighted(&[1e6])), [Sole]);
        assert_eq!(shares(&weighted(&[0.0, 0.0])), [Unknown, Unknown]);
    }

    #[test]
    fn a_share_reads_as_a_percentage_of_at_most_100() {
        use HypothesisShare::*;
        let read = |s: HypothesisShare| s.to_string();
        assert_eq!(read(Fraction(0.7)), "70 %");
        assert_eq!(read(Fraction(1.0)), "100 %");
        assert_eq!(read(Fraction(0.001)), "< 1 %");
        assert_eq!(read(Fraction(0.0)), "0 %");
        assert_eq!(read(Sole), "sole hypothesis");
        assert_eq!(read(Unknown), "share unknown");
    }

    #[test]
    fn unusable_weights_are_neither_shared_nor_best() {
        use HypothesisShare::*;
        let data = weighted(&[f64::NAN, 0.2, -1.0]);
        assert_eq!(shares(&data), [Unknown, Unknown, Unknown]);
        assert_eq!(
            data.best().map(|h| h.mean.px),
            Some(1.0),
            "NaN is not the heaviest"
        );
        let none_usable = weighted(&[f64::NAN, -2.0, f64::INFINITY]);
        assert_eq!(
            none_usable.best().map(|h| h.mean.px),
            Some(0.0),
            "the first, then"
        );
    }
}

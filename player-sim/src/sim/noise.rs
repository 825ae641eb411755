//! Seeded sensor noise: Gaussian range noise that is a pure function of the seed, the step, the
//! robot, the sensor and the beam, so a run is reproduced exactly by its seed whatever order
//! devices are read or subscribed in, and no state is shared between threads. A sensor's own
//! `noise` (Stage's: a world file property, none by default) is drawn the same way.

use crate::world::RangerNoise;

/// How noisy the rangers are (`--range-noise`, on top of any noise a sensor sets itself).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Noise {
    /// Seeds every draw (`--seed`).
    pub seed: u64,
    /// Standard deviation of a range reading, m (`--range-noise`); 0 gives exact readings.
    pub range_sd: f64,
}

/// splitmix64's finaliser: a well-mixed 64-bit value from any 64-bit value.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A uniform value in (0, 1) from 53 well-mixed bits.
fn unit(bits: u64) -> f64 {
    ((bits >> 11) as f64 + 0.5) / (1u64 << 53) as f64
}

/// Keep the draws of a sensor's own (Stage) noise apart from one another and from the rest.
const STAGE_GAUSSIAN: u64 = 0x5747_4745_0000_0001;
const STAGE_SHARE: u64 = 0x5747_4745_0000_0002;
const STAGE_TURN: u64 = 0x5747_4745_0000_0003;

impl Noise {
    fn key(&self, coordinates: &[u64]) -> u64 {
        coordinates
            .iter()
            .fold(mix(self.seed), |acc, &c| mix(acc ^ c))
    }

    fn normal_at(key: u64) -> f64 {
        let (u1, u2) = (unit(mix(key)), unit(mix(key ^ 0xA5A5_A5A5_A5A5_A5A5)));
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }

    /// A standard normal draw for the given coordinates (Box–Muller on two hashed uniforms).
    pub fn normal(&self, coordinates: &[u64]) -> f64 {
        Self::normal_at(self.key(coordinates))
    }

    /// A uniform draw in (0, 1) for the given coordinates (for choices such as how long a
    /// wandering robot keeps turning).
    pub fn uniform(&self, coordinates: &[u64]) -> f64 {
        unit(mix(self.key(coordinates)))
    }

    /// A beam's `range` (it hit something) with its sensor's own noise, as Stage 4.3 adds it
    /// (a uniform share of the range and a Gaussian of the sensor's variance, not held to the
    /// sensor's range), then the run's `--range-noise` ([`Self::range`]).
    pub fn reading(
        &self,
        range: f64,
        sensor: &RangerNoise,
        (min, max): (f64, f64),
        coordinates: &[u64],
    ) -> f64 {
        let key = self.key(coordinates);
        let mut noisy = range;
        if sensor.range_share != 0.0 {
            let share = 2.0 * unit(mix(key ^ STAGE_SHARE)) - 1.0;
            noisy += range * sensor.range_share * share;
        }
        if sensor.range_variance > 0.0 {
            noisy += sensor.range_variance.sqrt() * Self::normal_at(key ^ STAGE_GAUSSIAN);
        }
        self.range(noisy, min, max, coordinates)
    }

    /// How far a beam turns from its direction with its sensor's angular noise, radians: up
    /// to ± half the noise times the beams' `spacing`, uniformly, as Stage 4.3 turns it.
    pub fn beam_turn(&self, sensor: &RangerNoise, spacing: f64, coordinates: &[u64]) -> f64 {
        if sensor.angular == 0.0 {
            return 0.0;
        }
        let share = 2.0 * unit(mix(self.key(coordinates) ^ STAGE_TURN)) - 1.0;
        spacing * sensor.angular * share * 0.5
    }

    /// `range` with noise for the given coordinates, kept within `[min, max]`.
    pub fn range(&self, range: f64, min: f64, max: f64, coordinates: &[u64]) -> f64 {
        if self.range_sd <= 0.0 {
            return range;
        }
        (range + self.range_sd * self.normal(coordinates)).clamp(min, max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn draws_are_reproducible_normal_and_depend_on_the_seed() {
        let a = Noise {
            seed: 7,
            range_sd: 0.1,
        };
        let draws: Vec<f64> = (0..20_000).map(|i| a.normal(&[i, 3])).collect();
        let again: Vec<f64> = (0..20_000).map(|i| a.normal(&[i, 3])).collect();
        assert_eq!(draws, again);
        let mean = draws.iter().sum::<f64>() / draws.len() as f64;
        let var = draws.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / draws.len() as f64;
        assert!(
            mean.abs() < 0.03 && (var - 1.0).abs() < 0.05,
            "{mean} {var}"
        );
        let b = Noise { seed: 8, ..a };
        assert_ne!(a.normal(&[1, 3]), b.normal(&[1, 3]));
        assert_eq!(Noise::default().range(2.0, 0.0, 8.0, &[1]), 2.0);
        assert!((0..100).all(|i| (0.0..=8.0).contains(&a.range(7.99, 0.0, 8.0, &[i]))));
    }
}

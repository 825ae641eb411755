//! Seeded sensor noise: Gaussian range noise that is a pure function of the seed, the step, the
//! robot, the sensor and the beam, so a run is reproduced exactly by its seed whatever order
//! devices are read or subscribed in, and no state is shared between threads.

/// How noisy the rangers are.
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

impl Noise {
    /// A standard normal draw for the given coordinates (Box–Muller on two hashed uniforms).
    pub fn normal(&self, coordinates: &[u64]) -> f64 {
        let key = coordinates
            .iter()
            .fold(mix(self.seed), |acc, &c| mix(acc ^ c));
        let (u1, u2) = (unit(mix(key)), unit(mix(key ^ 0xA5A5_A5A5_A5A5_A5A5)));
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }

    /// A uniform draw in (0, 1) for the given coordinates (for choices such as how long a
    /// wandering robot keeps turning).
    pub fn uniform(&self, coordinates: &[u64]) -> f64 {
        let key = coordinates
            .iter()
            .fold(mix(self.seed), |acc, &c| mix(acc ^ c));
        unit(mix(key))
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

//! Division by a ray's constants as a multiplication. A jump's length along the stepping
//! pattern takes a division or two by twice the ray's columns or rows (`free_steps`), at every
//! jump, each on the way to the next cell read; a 64-bit division waits 10 to 20 cycles, a
//! multiplication 3 or 4 (cheap enough that even a jump of a cell or two is divided, not
//! stepped). Where dividend and divisor fit 32 bits, `n / d` is the high word of
//! `n × (⌊(2⁶⁴ − 1) / d⌋ + 1)` exactly (Lemire, Kaser and Kurz, "Faster remainder by direct
//! computation", 2019): the multiplier is worked out once a ray.

/// Divisors below this take their multiplier from [`MULTIPLIERS`]: every ray works out two
/// (twice its columns and twice its rows, a few hundred in the cave), and each is a 64-bit
/// division of its own.
const TABLED: usize = 2048;

/// The multiplier of each divisor below [`TABLED`] (none for 0 and 1), worked out when built.
static MULTIPLIERS: [u64; TABLED] = {
    let mut table = [0; TABLED];
    let mut d = 2;
    while d < TABLED {
        table[d] = u64::MAX / d as u64 + 1;
        d += 1;
    }
    table
};

/// A divisor (at least 1) for dividends from 0 to a bound given with it.
#[derive(Debug, Clone, Copy)]
pub(in crate::sim) struct Divisor {
    d: i64,
    /// The multiplier, or 0 where the division is done as one.
    by: u64,
}

impl Divisor {
    /// Division by `d` (taken as 1 if less) of dividends up to `most`.
    pub(in crate::sim) fn new(d: i64, most: i64) -> Divisor {
        let d = d.max(1);
        let fits = |v: i64| v < 1 << 32;
        let by = if d >= 2 && fits(d) && fits(most) {
            match MULTIPLIERS.get(d as usize) {
                Some(&by) => by,
                None => u64::MAX / d as u64 + 1,
            }
        } else {
            0
        };
        Divisor { d, by }
    }

    /// `⌊n / d⌋` for `n` from 0 to the bound.
    #[inline(always)]
    pub(in crate::sim) fn floor_of(self, n: i64) -> i64 {
        // The multiplication is exact only for a dividend of 32 bits; the caller's bound
        // promises one (checked where debug assertions are on, as in the tests).
        debug_assert!(n >= 0 && (self.by == 0 || n < 1 << 32), "{n} / {}", self.d);
        if self.by != 0 {
            ((u128::from(self.by) * n as u128) >> 64) as i64
        } else {
            n / self.d
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::test_randoms::randoms;

    #[test]
    fn the_multiplication_divides_exactly() {
        let mut next = randoms(0xd1_7150);
        let top = (1i64 << 32) - 1;
        for _ in 0..20_000 {
            let d = 1 + (next() * next() * 5e5) as i64;
            let most = [top, 1 << 20, top / d][(next() * 3.0) as usize];
            let divisor = Divisor::new(d, most);
            assert!(d < 2 || divisor.by != 0, "{d} {most}");
            for n in [
                0,
                1,
                d - 1,
                d,
                d + 1,
                most,
                most - d % most,
                (next() * most as f64) as i64,
            ] {
                let n = n.clamp(0, most);
                assert_eq!(divisor.floor_of(n), n / d, "{n} / {d}");
            }
        }
        // Beyond 32 bits it divides.
        let big = Divisor::new(3, 1 << 40);
        assert_eq!(big.by, 0);
        assert_eq!(big.floor_of((1 << 40) - 1), ((1 << 40) - 1) / 3);
    }
}

//! A small deterministic generator (xorshift) for the ray and index tests' random
//! arrangements, without a dependency.

/// Numbers in [0, 1) from `state`, the same sequence for the same seed.
pub fn randoms(mut state: u64) -> impl FnMut() -> f64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

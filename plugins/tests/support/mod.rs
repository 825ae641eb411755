//! The framework's test harness, making plugins from the standard registry.

#![allow(dead_code)] // each test file uses its own part

pub mod position2d;

pub use framework::testing::Harness;

/// A harness whose `make` knows every standard plugin.
pub fn harness() -> Harness {
    Harness::with_registry(plugins::standard_plugins())
}

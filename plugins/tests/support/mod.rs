//! The framework's test harness, making plugins from the standard registry.

pub use framework::testing::Harness;

/// A harness whose `make` knows every standard plugin.
pub fn harness() -> Harness {
    Harness::with_registry(plugins::standard_plugins())
}

//! The framework's test harness, making plugins from the standard registry.

#![allow(dead_code)] // each test file uses its own part

pub mod position2d;

pub use framework::testing::Harness;

/// A harness whose `make` knows every standard plugin.
pub fn harness() -> Harness {
    Harness::with_registry(plugins::standard_plugins())
}

/// Plugin `library`, called `id`, for `addr` on localhost:6665 (Stage's driver), hanging below
/// its robot (`<parentNode interface="position2d"/>`) and with `params` after that; errors
/// name `test.xml:1:1`.
pub fn on_robot(
    library: &str,
    id: &str,
    addr: &str,
    params: Vec<framework::config::Param>,
) -> framework::PluginConfig {
    let mut parent = framework::config::Param::new("parentNode", "");
    parent.attributes = vec![("interface".into(), "position2d".into())];
    framework::PluginConfig {
        library: library.into(),
        id: id.into(),
        device: Some(framework::config::DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: addr.parse().unwrap(),
            driver: "stage".into(),
        }),
        params: std::iter::once(parent).chain(params).collect(),
        origin: "test.xml:1:1".into(),
        ..framework::PluginConfig::default()
    }
}

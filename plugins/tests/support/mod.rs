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

/// Every message the server sent in the repository's capture `name` (a path under
/// `captures/`, or under `PLAYER_CAPTURES_DIR`), decoded, in order.
pub fn captured_messages(name: &str) -> Vec<player_proto::message::Message> {
    use player_proto::capture::{Direction, parse_capture, stream};
    use player_proto::message::Message;
    use player_proto::wire::FrameDecoder;

    let path = std::env::var_os("PLAYER_CAPTURES_DIR")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../captures"))
        .join(name);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("missing capture {}: {e}", path.display()));
    let bytes = stream(&parse_capture(&text).unwrap(), Direction::ServerToClient);
    let mut frames = FrameDecoder::default();
    frames.extend(&bytes);
    frames.take_banner().unwrap().unwrap();
    let mut messages = Vec::new();
    while let Some(frame) = frames.next_frame().unwrap() {
        messages.push(Message::decode(frame.header, frame.body).unwrap());
    }
    messages
}

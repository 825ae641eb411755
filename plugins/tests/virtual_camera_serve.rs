//! A virtual camera with `servePort` is a Player camera: a Player client connects, subscribes to
//! `camera:0` and receives the rendered picture the right way up. A port that is taken or not a
//! port is refused with the parameter named.

mod support;

use std::net::TcpListener;
use std::time::{Duration, Instant};

use framework::PluginConfig;
use framework::config::Param;
use framework::scene::{PixelFormat, Pixels};
use player_proto::DevAddr;
use player_proto::client::{Client, ClientOptions};
use support::harness;

fn config(port: &str) -> PluginConfig {
    PluginConfig {
        library: "libpv3d_virtual_camera".into(),
        id: "served".into(),
        params: vec![
            Param::new("width", "8"),
            Param::new("height", "6"),
            Param::new("servePort", port),
        ],
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    }
}

/// A port nobody listens on right now.
fn free_port() -> u16 {
    TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port()
}

#[test]
fn a_player_client_receives_the_rendered_picture() {
    let port = free_port();
    let mut h = harness();
    let mut plugin = h.make(config(&port.to_string())).unwrap();
    let client = Client::connect("127.0.0.1", port, ClientOptions::default()).unwrap();
    let camera = DevAddr {
        robot: u32::from(port),
        .."camera:0".parse::<DevAddr>().unwrap()
    };
    client.subscribe(camera).unwrap();

    // What the viewer would render: green, with a red bottom row.
    let mut bytes = [0u8, 200, 0, 255].repeat(8 * 6);
    bytes[..8 * 4].copy_from_slice(&[220u8, 0, 0, 255].repeat(8));
    let node = plugin.node().unwrap();
    let view = h.scene.get(node).unwrap().geometry.views[0].clone();
    view.output
        .deliver(Pixels::new(8, 6, PixelFormat::Rgba8, bytes).unwrap());
    plugin.run(&mut h.ctx());

    let deadline = Instant::now() + Duration::from_secs(5);
    let frame = loop {
        if let Some((frame, _)) = client.camera(0).frame() {
            break frame;
        }
        assert!(Instant::now() < deadline, "no frame reached the client");
        std::thread::sleep(Duration::from_millis(10));
    };
    let image = frame.to_rgba().unwrap();
    assert_eq!(image.dimensions(), (8, 6));
    assert_eq!(image.get_pixel(3, 5).0, [220, 0, 0, 255], "bottom row red");
    assert_eq!(image.get_pixel(3, 0).0, [0, 200, 0, 255], "top green");
}

#[test]
fn a_taken_or_impossible_port_is_refused_with_the_parameter_named() {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let taken = listener.local_addr().unwrap().port().to_string();
    for port in [taken.as_str(), "70000", "0", "http", "6665.5"] {
        let error = harness()
            .make(config(port))
            .err()
            .unwrap_or_else(|| panic!("servePort {port} is refused"));
        assert!(error.to_string().contains("servePort"), "{port}: {error}");
    }
}

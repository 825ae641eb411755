//! The client's notifier runs whenever there is something new to read — data, and also a
//! change of connection state such as a handshake completed with no data at all, so that a viewer learns of a server that answered
//! late before any of its devices is subscribed.

use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;

use player_proto::client::{Client, ClientOptions, ConnectionState};
use player_proto::server::{Device, Server, ServerConfig};

struct Quiet;
impl Device for Quiet {
    fn driver_name(&self) -> &str {
        "quiet"
    }
}

#[test]
fn a_completed_handshake_notifies_even_without_data() {
    let mut config = ServerConfig::default();
    let robot = config.robot(0);
    config.device(robot, "position2d:0".parse().unwrap(), Quiet);
    let server = Server::start(config).unwrap();

    let calls = Arc::new(AtomicUsize::new(0));
    let (told, notified) = std::sync::mpsc::channel();
    let counted = calls.clone();
    let options = ClientOptions {
        notifier: Some(Arc::new(move || {
            counted.fetch_add(1, Ordering::SeqCst);
            let _ = told.send(());
        })),
        ..ClientOptions::default()
    };
    let client = Client::connect("127.0.0.1", server.port(0), options).unwrap();
    assert_eq!(client.state(), ConnectionState::Connected);
    notified
        .recv_timeout(Duration::from_secs(2))
        .expect("the handshake notifies");
    // Connecting, then Connected: state changes only, for no data was asked for.
    let calls = calls.load(Ordering::SeqCst);
    assert!((1..=2).contains(&calls), "{calls} calls");
}

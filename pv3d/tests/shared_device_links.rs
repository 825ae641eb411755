//! The robot manager really counts the plugins that use a device: two plugins share one
//! subscription, the first one letting go leaves it in place, and the last one letting go
//! unsubscribes — which a real Player server, over TCP, sees as the device being closed.

use std::sync::mpsc;
use std::time::Duration;

use framework::config::DeviceRef;
use player_proto::client::DataMode;
use player_proto::message::Message;
use player_proto::server::{Device, Reply, Server, ServerConfig};
use player_proto::wire::DevAddr;
use pv3d::composition::{ClientDecl, SourcePos};
use pv3d::robots::RobotManager;

/// Longest wait for the server to see something that is on its way.
const PATIENCE: Duration = Duration::from_secs(5);

#[derive(Debug, PartialEq)]
enum Seen {
    Opened,
    Closed,
}

/// A laser that only tells the test when a client opens or closes it.
struct WatchedLaser(mpsc::Sender<Seen>);

impl Device for WatchedLaser {
    fn driver_name(&self) -> &str {
        "watched"
    }
    fn on_subscribe(&mut self) -> bool {
        let _ = self.0.send(Seen::Opened);
        true
    }
    fn on_unsubscribe(&mut self) {
        let _ = self.0.send(Seen::Closed);
    }
    fn on_request(&mut self, _request: &Message) -> Reply {
        Reply::Nack
    }
}

#[test]
fn the_last_plugin_to_let_a_device_go_unsubscribes_it() {
    let (seen, server_saw) = mpsc::channel();
    let mut config = ServerConfig::default();
    let robot = config.robot(0);
    let laser: DevAddr = "laser:0".parse().unwrap();
    config.device(robot, laser, WatchedLaser(seen));
    let server = Server::start(config).unwrap();
    let port = server.port(robot);

    let robots = RobotManager::start(
        &[ClientDecl {
            host: "127.0.0.1".into(),
            port,
            pos: SourcePos::generated(),
        }],
        None,
    );
    robots.wait_for_handshakes(PATIENCE);
    let client = robots.client("127.0.0.1", port).unwrap().clone();
    // A request answered after everything sent before it: the server has handled those.
    let round_trip = || client.set_data_mode(DataMode::Push).unwrap();
    let device = DeviceRef {
        host: "127.0.0.1".into(),
        port,
        addr: laser,
        driver: "watched".into(),
    };

    let first_plugin = robots.device(&device).unwrap();
    let second_plugin = robots.device(&device).unwrap();
    assert_eq!(server_saw.recv_timeout(PATIENCE), Ok(Seen::Opened));
    round_trip();
    assert!(server_saw.try_recv().is_err(), "one subscription for both");
    assert_eq!(robots.used_devices().len(), 1);

    drop(first_plugin);
    round_trip();
    assert!(
        server_saw.try_recv().is_err(),
        "the second plugin still uses the device"
    );
    assert_eq!(robots.used_devices().len(), 1);

    drop(second_plugin);
    assert_eq!(server_saw.recv_timeout(PATIENCE), Ok(Seen::Closed));
    assert!(robots.used_devices().is_empty());

    // Wanted again: subscribed again.
    let _again = robots.device(&device).unwrap();
    assert_eq!(server_saw.recv_timeout(PATIENCE), Ok(Seen::Opened));
}

//! A server of two robots for the server-side protocol tests: on the first, a laser that
//! answers its geometry and counts subscriptions, one that refuses them, and a base that
//! records its commands; on the second, another base.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

use player_proto::interfaces::common::{BBox3d, Pose3d};
use player_proto::interfaces::laser::{Laser, LaserGeometry};
use player_proto::message::{Body, Message};
use player_proto::server::{Device, Reply, Server, ServerConfig};

/// A laser that answers GET_GEOM and counts subscriptions.
pub struct TestLaser {
    pub subscribers: Arc<AtomicUsize>,
    pub refuse: bool,
}

impl Device for TestLaser {
    fn driver_name(&self) -> &str {
        "sicklms200"
    }
    fn on_subscribe(&mut self) -> bool {
        self.subscribers.fetch_add(1, Ordering::SeqCst);
        !self.refuse
    }
    fn on_unsubscribe(&mut self) {
        self.subscribers.fetch_sub(1, Ordering::SeqCst);
    }
    fn on_request(&mut self, request: &Message) -> Reply {
        match request.header.subtype {
            1 => Reply::Ack(Body::Laser(Laser::Geometry(LaserGeometry {
                pose: Pose3d {
                    px: 0.1,
                    ..Pose3d::default()
                },
                size: BBox3d {
                    sw: 0.15,
                    sl: 0.15,
                    sh: 0.1,
                },
            }))),
            _ => Reply::Nack,
        }
    }
}

/// A base that records its commands.
pub struct TestBase(pub Arc<Mutex<Vec<Message>>>);

impl Device for TestBase {
    fn driver_name(&self) -> &str {
        "stage"
    }
    fn on_command(&mut self, command: &Message) {
        self.0.lock().unwrap().push(command.clone());
    }
}

pub struct Fixture {
    pub server: Server,
    pub subscribers: Arc<AtomicUsize>,
    pub commands: Arc<Mutex<Vec<Message>>>,
}

pub fn fixture() -> Fixture {
    let subscribers = Arc::new(AtomicUsize::new(0));
    let commands = Arc::new(Mutex::new(Vec::new()));
    let mut config = ServerConfig::default();
    let a = config.robot(0);
    let b = config.robot(0);
    config.device(
        a,
        "laser:0".parse().unwrap(),
        TestLaser {
            subscribers: subscribers.clone(),
            refuse: false,
        },
    );
    config.device(
        a,
        "laser:1".parse().unwrap(),
        TestLaser {
            subscribers: Arc::default(),
            refuse: true,
        },
    );
    config.device(
        a,
        "position2d:0".parse().unwrap(),
        TestBase(commands.clone()),
    );
    config.device(b, "position2d:0".parse().unwrap(), TestBase(Arc::default()));
    Fixture {
        server: Server::start(config).unwrap(),
        subscribers,
        commands,
    }
}

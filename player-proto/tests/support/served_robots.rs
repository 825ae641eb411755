//! Robots served by player-proto's own server for the client's tests: a laser and a base, a
//! feeder publishing scans, and waits bounded in time.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use player_proto::client::{Backoff, Client, ClientOptions, ConnectionState};
use player_proto::interfaces::common::{BBox3d, Pose3d};
use player_proto::interfaces::laser::{Laser, LaserGeometry, LaserScan};
use player_proto::message::{Body, Message};
use player_proto::server::{Device, Publisher, Reply, Server, ServerConfig};
use player_proto::wire::DevAddr;

pub struct Laser0;
impl Device for Laser0 {
    fn driver_name(&self) -> &str {
        "sicklms200"
    }
    fn on_request(&mut self, request: &Message) -> Reply {
        match request.header.subtype {
            1 => Reply::Ack(Body::Laser(Laser::Geometry(LaserGeometry {
                pose: Pose3d {
                    px: 0.12,
                    ..Pose3d::default()
                },
                size: BBox3d {
                    sw: 0.1,
                    sl: 0.1,
                    sh: 0.1,
                },
            }))),
            _ => Reply::Nack,
        }
    }
}

pub struct Base(Arc<Mutex<Vec<Message>>>);
impl Device for Base {
    fn driver_name(&self) -> &str {
        "stage"
    }
    fn on_command(&mut self, command: &Message) {
        self.0.lock().unwrap().push(command.clone());
    }
    fn on_request(&mut self, _: &Message) -> Reply {
        Reply::Ack(Body::Empty)
    }
}

pub fn server(port: u16, commands: Arc<Mutex<Vec<Message>>>) -> Server {
    let mut config = ServerConfig::default();
    let robot = config.robot(port);
    config.device(robot, "laser:0".parse().unwrap(), Laser0);
    config.device(robot, "position2d:0".parse().unwrap(), Base(commands));
    Server::start(config).unwrap()
}

pub fn addr(server: &Server, text: &str) -> DevAddr {
    let mut a: DevAddr = text.parse().unwrap();
    a.robot = u32::from(server.port(0));
    a
}

pub fn scan(id: u32) -> Body {
    Body::Laser(Laser::Scan(LaserScan {
        ranges: vec![1.5; 361],
        max_range: 8.0,
        id,
        ..LaserScan::default()
    }))
}

/// Publishes a scan every 10 ms until dropped.
pub struct Feeder {
    stop: Arc<AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Feeder {
    pub fn start(publisher: Publisher, at: DevAddr) -> Feeder {
        let stop = Arc::new(AtomicBool::new(false));
        let flag = stop.clone();
        let thread = std::thread::spawn(move || {
            let mut id = 0;
            while !flag.load(Ordering::Relaxed) {
                publisher.publish(at, 1, scan(id), f64::from(id) * 0.01);
                id += 1;
                std::thread::sleep(Duration::from_millis(10));
            }
        });
        Feeder {
            stop,
            thread: Some(thread),
        }
    }
}

impl Drop for Feeder {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

pub fn wait_for(what: &str, timeout: Duration, mut ok: impl FnMut() -> bool) {
    let deadline = Instant::now() + timeout;
    while !ok() {
        assert!(Instant::now() < deadline, "timed out waiting for {what}");
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// Waits on the client's state signal.
pub fn wait_for_state(
    client: &Client,
    what: &str,
    timeout: Duration,
    done: impl FnMut(&ConnectionState) -> bool,
) {
    if client.wait_for_state(timeout, done).is_none() {
        panic!("timed out waiting for {what}: {}", client.state());
    }
}

pub fn quick() -> ClientOptions {
    ClientOptions {
        request_timeout: Duration::from_secs(2),
        backoff: Backoff {
            initial: Duration::from_millis(50),
            max: Duration::from_millis(200),
            max_attempts: None,
        },
        ..ClientOptions::default()
    }
}

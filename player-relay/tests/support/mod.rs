//! What the relay's tests share: a mock robot (a `player_proto::server` with a base that
//! records commands and a laser published on demand), observers (ordinary clients through the
//! relay), and a raw observer that reads only when told.

#![allow(dead_code)]

use std::io::{Read, Write};
use std::net::TcpStream;
use std::sync::mpsc::{Receiver, Sender, channel, sync_channel};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use player_proto::client::{Backoff, Client, ClientOptions};
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::interfaces::player::{self, DeviceReq, Player};
use player_proto::interfaces::position2d::{self, Position2d, Position2dGeometry};
use player_proto::message::{Body, Message};
use player_proto::server::{Device, Reply, Server, ServerConfig};
use player_proto::wire::{Banner, DevAddr, FrameDecoder, Interface, MsgType, PlayerString};
use player_relay::{Relay, RelayConfig, Route};

/// Long enough for anything on loopback; only reached when something is broken.
pub const PATIENCE: Duration = Duration::from_secs(10);
/// Beams of the mock laser, as in the benchmark.
pub const BEAMS: usize = 361;

/// The base: commands go to the test, geometry is answered, motor power is ACKed.
struct Base(Sender<Message>);

impl Device for Base {
    fn driver_name(&self) -> &str {
        "mockbase"
    }

    fn on_command(&mut self, command: &Message) {
        let _ = self.0.send(command.clone());
    }

    fn on_request(&mut self, request: &Message) -> Reply {
        match request.header.subtype {
            position2d::REQ_GET_GEOM => Reply::Ack(Body::Position2d(Position2d::Geometry(
                Position2dGeometry::default(),
            ))),
            _ => {
                let _ = self.0.send(request.clone());
                Reply::Ack(Body::Empty)
            }
        }
    }
}

struct MockLaser;

impl Device for MockLaser {
    fn driver_name(&self) -> &str {
        "mocklaser"
    }
}

/// A robot server with `position2d:0` and `laser:0`.
pub struct Robot {
    pub server: Server,
    /// Commands and requests (other than geometry) the base received.
    pub received: Receiver<Message>,
}

impl Robot {
    /// Serves on `port` (0: any free one).
    pub fn start(port: u16) -> Robot {
        let (sender, received) = channel();
        let mut config = ServerConfig::default();
        let robot = config.robot(port);
        config.device(
            robot,
            DevAddr::local(Interface::POSITION2D, 0),
            Base(sender),
        );
        config.device(robot, DevAddr::local(Interface::LASER, 0), MockLaser);
        Robot {
            server: Server::start(config).expect("robot server"),
            received,
        }
    }

    pub fn port(&self) -> u16 {
        self.server.port(0)
    }

    /// Publishes a scan whose `id` says which one it is.
    pub fn publish_scan(&self, id: u32) -> usize {
        let scan = LaserScan {
            ranges: vec![1.5; BEAMS],
            id,
            ..LaserScan::default()
        };
        let mut addr = DevAddr::local(Interface::LASER, 0);
        addr.robot = u32::from(self.port());
        self.server
            .publisher()
            .publish(addr, 1, Body::Laser(Laser::Scan(scan)), 0.0)
    }
}

/// A relay in front of `robot`, served on any free port.
pub fn relay_for(robot: &Robot, config: RelayConfig) -> (Relay, u16) {
    let relay = Relay::start(RelayConfig {
        routes: vec![Route::loopback(robot.port())],
        upstream: quick(),
        ..config
    })
    .expect("relay");
    assert_eq!(
        relay.wait_serving(PATIENCE),
        1,
        "the relay serves the robot"
    );
    let port = relay.robots()[0].listen_port().expect("bound");
    (relay, port)
}

/// Client options that notice and retry quickly.
pub fn quick() -> ClientOptions {
    ClientOptions {
        connect_timeout: Duration::from_secs(2),
        request_timeout: Duration::from_secs(2),
        backoff: Backoff {
            initial: Duration::from_millis(20),
            max: Duration::from_millis(100),
            max_attempts: None,
        },
        ..ClientOptions::default()
    }
}

/// An ordinary client through the relay, with a signal on new data and state changes.
pub struct Observer {
    pub client: Client,
    pub woken: Receiver<()>,
}

impl Observer {
    pub fn connect(port: u16) -> Observer {
        let (wake, woken) = sync_channel(1);
        let options = ClientOptions {
            notifier: Some(Arc::new(move || {
                let _ = wake.try_send(());
            })),
            ..quick()
        };
        let client = Client::connect("127.0.0.1", port, options).expect("observer connects");
        client
            .laser(0)
            .subscribe()
            .expect("subscribed to the laser");
        Observer { client, woken }
    }

    /// The id of the newest scan, if one came.
    pub fn newest_scan(&self) -> Option<u32> {
        self.client.laser(0).scan().map(|(scan, _)| scan.id)
    }

    /// Waits until the newest scan satisfies `done`; false if it did not within `PATIENCE`.
    pub fn wait_for_scan(&self, done: impl Fn(u32) -> bool) -> bool {
        let deadline = Instant::now() + PATIENCE;
        loop {
            if self.newest_scan().is_some_and(&done) {
                return true;
            }
            let left = deadline.saturating_duration_since(Instant::now());
            if left.is_zero() || self.woken.recv_timeout(left).is_err() {
                return false;
            }
        }
    }
}

/// Publishes scan after scan until every observer has one (the relay subscribes upstream
/// when the first observer subscribes, so the first scans may reach nobody); returns the id
/// of the last scan published.
pub fn publish_until_seen(robot: &Robot, observers: &[&Observer], first_id: u32) -> u32 {
    let deadline = Instant::now() + PATIENCE;
    let mut id = first_id;
    loop {
        robot.publish_scan(id);
        let all = observers.iter().all(|o| {
            o.woken.recv_timeout(Duration::from_millis(20)).ok();
            o.newest_scan().is_some_and(|seen| seen >= first_id)
        });
        if all {
            return id;
        }
        assert!(Instant::now() < deadline, "no scan reached every observer");
        id += 1;
    }
}

/// An observer over a plain socket, which reads only when the test says so.
pub struct RawObserver {
    stream: TcpStream,
    frames: FrameDecoder,
}

impl RawObserver {
    /// Connects and subscribes to the laser, reading until the subscription's ACK.
    pub fn subscribe(port: u16) -> RawObserver {
        let mut stream = TcpStream::connect(("127.0.0.1", port)).expect("connect");
        stream.set_read_timeout(Some(PATIENCE)).unwrap();
        let mut banner = [0u8; 32];
        stream.read_exact(&mut banner).expect("banner");
        Banner::parse(&banner).expect("a Player banner");
        let open = DeviceReq {
            addr: DevAddr::local(Interface::LASER, 0),
            access: player::OPEN_MODE,
            driver_name: PlayerString::default(),
        };
        let open = Message::new(
            DevAddr::local(Interface::PLAYER, 0),
            MsgType::Req,
            player::REQ_DEV,
            Body::Player(Player::Device(open)),
        );
        stream.write_all(&open.to_bytes()).unwrap();
        let mut raw = RawObserver {
            stream,
            frames: FrameDecoder::default(),
        };
        let ack = raw.next().expect("the subscription's reply");
        assert_eq!(ack.header.msg_type, MsgType::Ack);
        raw
    }

    /// The next message, `None` if the relay closed or nothing came in time.
    pub fn next(&mut self) -> Option<Message> {
        loop {
            if let Some(frame) = self.frames.next_frame().expect("good framing") {
                return Some(Message::decode(frame.header, frame.body).expect("decodable"));
            }
            let mut buf = [0u8; 4096];
            match self.stream.read(&mut buf) {
                Ok(0) | Err(_) => return None,
                Ok(n) => self.frames.extend(&buf[..n]),
            }
        }
    }
}

/// The scan id in a laser DATA message.
pub fn scan_id(message: &Message) -> Option<u32> {
    match &message.body {
        Body::Laser(Laser::Scan(scan)) => Some(scan.id),
        _ => None,
    }
}

/// Shared log of what came, for assertions after the fact.
pub type Log<T> = Arc<Mutex<Vec<T>>>;

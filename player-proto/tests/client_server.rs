//! The client against the server module over real TCP: handshake, subscriptions, data, typed
//! requests and commands, PULL rounds, several robots, and a server that dies and comes back.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use player_proto::client::{
    Backoff, Client, ClientOptions, ConnectionState, DataMode, MultiClient, ReplaceAction,
    ReplaceRule, RequestError,
};
use player_proto::interfaces::common::{BBox3d, Pose2d, Pose3d};
use player_proto::interfaces::laser::{Laser, LaserGeometry, LaserScan};
use player_proto::interfaces::position2d::Position2d;
use player_proto::message::{Body, Message};
use player_proto::server::{Device, Publisher, Reply, Server, ServerConfig};
use player_proto::wire::{DevAddr, Interface};

struct Laser0;
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

struct Base(Arc<Mutex<Vec<Message>>>);
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

fn server(port: u16, commands: Arc<Mutex<Vec<Message>>>) -> Server {
    let mut config = ServerConfig::default();
    let robot = config.robot(port);
    config.device(robot, "laser:0".parse().unwrap(), Laser0);
    config.device(robot, "position2d:0".parse().unwrap(), Base(commands));
    Server::start(config).unwrap()
}

fn addr(server: &Server, text: &str) -> DevAddr {
    let mut a: DevAddr = text.parse().unwrap();
    a.robot = u32::from(server.port(0));
    a
}

fn scan(id: u32) -> Body {
    Body::Laser(Laser::Scan(LaserScan {
        ranges: vec![1.5; 361],
        max_range: 8.0,
        id,
        ..LaserScan::default()
    }))
}

/// Publishes a scan every 10 ms until dropped.
struct Feeder {
    stop: Arc<AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Feeder {
    fn start(publisher: Publisher, at: DevAddr) -> Feeder {
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

fn wait_for(what: &str, timeout: Duration, mut ok: impl FnMut() -> bool) {
    let deadline = Instant::now() + timeout;
    while !ok() {
        assert!(Instant::now() < deadline, "timed out waiting for {what}");
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// Waits on the client's state signal.
fn wait_for_state(
    client: &Client,
    what: &str,
    timeout: Duration,
    done: impl FnMut(&ConnectionState) -> bool,
) {
    if client.wait_for_state(timeout, done).is_none() {
        panic!("timed out waiting for {what}: {}", client.state());
    }
}

fn quick() -> ClientOptions {
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

#[test]
fn handshake_subscribe_and_data_with_freshness() {
    let s = server(0, Arc::default());
    let notified = Arc::new(AtomicUsize::new(0));
    let count = notified.clone();
    let options = ClientOptions {
        notifier: Some(Arc::new(move || {
            count.fetch_add(1, Ordering::Relaxed);
        })),
        ..quick()
    };
    let client = Client::connect("127.0.0.1", s.port(0), options).unwrap();
    assert_eq!(client.banner().unwrap().version, "3.1.1-dev");
    let devices = client.devices();
    assert_eq!(devices.len(), 2);
    assert!(
        devices
            .iter()
            .any(|d| d.addr.interf == Interface::LASER && d.driver == "sicklms200")
    );

    let laser = client.laser(0);
    assert_eq!(laser.subscribe().unwrap(), "sicklms200");
    let _feed = Feeder::start(s.publisher(), addr(&s, "laser:0"));
    wait_for("a scan", Duration::from_secs(3), || laser.scan().is_some());
    let (first, stamp1) = laser.scan().unwrap();
    assert_eq!(first.ranges.len(), 361);
    wait_for("a newer scan", Duration::from_secs(3), || {
        laser.scan().unwrap().1.seq > stamp1.seq
    });
    let (_, stamp2) = laser.scan().unwrap();
    assert!(stamp2.server_time > stamp1.server_time && stamp2.received >= stamp1.received);
    assert!(notified.load(Ordering::Relaxed) >= 2);
    assert!(client.stats(laser.addr()).messages >= 2);

    laser.unsubscribe().unwrap();
    assert!(
        laser.scan().is_none(),
        "data of an unsubscribed device is forgotten"
    );
}

#[test]
fn typed_requests_commands_nacks_and_timeouts() {
    let commands = Arc::new(Mutex::new(Vec::new()));
    let s = server(0, commands.clone());
    let client = Client::connect("127.0.0.1", s.port(0), quick()).unwrap();
    let geometry = client.laser(0).geometry().unwrap();
    assert_eq!(geometry.pose.px, 0.12);
    assert!(matches!(
        client.laser(0).config(),
        Err(RequestError::Nack(_))
    ));

    let base = client.position2d(0);
    base.subscribe().unwrap();
    base.set_motor_power(true).unwrap();
    base.set_velocity(0.5, 0.0, 0.25);
    base.go_to(Pose2d::new(1.0, 2.0, 0.0));
    wait_for("two commands", Duration::from_secs(3), || {
        commands.lock().unwrap().len() == 2
    });
    let got = commands.lock().unwrap();
    assert!(
        matches!(&got[0].body, Body::Position2d(Position2d::Velocity(v)) if v.vel.px == 0.5 && v.vel.pa == 0.25 && v.state == 1)
    );
    assert!(matches!(&got[1].body, Body::Position2d(Position2d::Position(p)) if p.pos.py == 2.0));

    // Player drops requests to devices it does not have: the request times out.
    let options = ClientOptions {
        request_timeout: Duration::from_millis(300),
        ..quick()
    };
    let impatient = Client::connect("127.0.0.1", s.port(0), options).unwrap();
    let started = Instant::now();
    assert!(matches!(
        impatient.sonar(3).geometry(),
        Err(RequestError::Timeout(_))
    ));
    assert!(started.elapsed() < Duration::from_secs(2));
    // Several requests in flight at once, each matched to its reply.
    let pending: Vec<_> = (0..8)
        .map(|_| client.fetch_async(client.addr(Interface::LASER, 0), Laser::REQ_GET_GEOM))
        .collect();
    for p in pending {
        assert!(matches!(
            p.wait(Duration::from_secs(3)).unwrap().body,
            Body::Laser(Laser::Geometry(_))
        ));
    }
    assert!(matches!(
        client.subscribe(client.addr(Interface::SONAR, 0)),
        Err(RequestError::Nack(_))
    ));
}

#[test]
fn pull_mode_rounds_bring_the_newest_data() {
    let s = server(0, Arc::default());
    let client = Client::connect(
        "127.0.0.1",
        s.port(0),
        ClientOptions {
            data_mode: DataMode::Pull,
            ..quick()
        },
    )
    .unwrap();
    client.laser(0).subscribe().unwrap();
    for id in 0..20 {
        s.publisher().publish(addr(&s, "laser:0"), 1, scan(id), 0.0);
    }
    std::thread::sleep(Duration::from_millis(100));
    assert!(
        client.laser(0).scan().is_none(),
        "PULL: nothing until asked"
    );
    assert_eq!(
        client.pull().unwrap(),
        1,
        "the replace rule left only the newest scan"
    );
    assert_eq!(client.laser(0).scan().unwrap().0.id, 19);
    for id in 20..23 {
        s.publisher().publish(addr(&s, "laser:0"), 1, scan(id), 0.0);
        assert_eq!(client.pull().unwrap(), 1);
    }
    assert_eq!(
        client.rejected(),
        0,
        "a data request's ACK is expected, not a reply to nothing"
    );
}

#[test]
fn many_robots_flow_while_one_is_unreachable() {
    let servers: Vec<Server> = (0..3).map(|_| server(0, Arc::default())).collect();
    let dead_port = {
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        l.local_addr().unwrap().port()
    };
    let mut robots = MultiClient::new();
    for s in &servers {
        robots.add("127.0.0.1", s.port(0), quick()).unwrap();
    }
    robots.add("127.0.0.1", dead_port, quick()).unwrap();
    assert_eq!(robots.wait_for_handshakes(Duration::from_secs(5)), 3);
    let feeds: Vec<Feeder> = servers
        .iter()
        .map(|s| Feeder::start(s.publisher(), addr(s, "laser:0")))
        .collect();
    for i in 0..3 {
        robots.get(i).unwrap().laser(0).subscribe().unwrap();
    }
    for i in 0..3 {
        wait_for("every live robot's scans", Duration::from_secs(3), || {
            robots.get(i).unwrap().laser(0).scan().is_some()
        });
    }
    assert!(matches!(
        robots.get(3).unwrap().state(),
        ConnectionState::Reconnecting { .. } | ConnectionState::Connecting
    ));
    let started = Instant::now();
    assert!(robots.get(3).unwrap().laser(0).geometry().is_err());
    assert!(
        started.elapsed() < Duration::from_secs(3),
        "an unreachable robot answers fast, never hangs"
    );
    drop(feeds);
}

#[test]
fn a_restarted_server_gets_its_subscriptions_back() {
    let s = server(0, Arc::default());
    let port = s.port(0);
    let client = Client::connect("127.0.0.1", port, quick()).unwrap();
    client.laser(0).subscribe().unwrap();
    let feed = Feeder::start(s.publisher(), addr(&s, "laser:0"));
    wait_for("data", Duration::from_secs(3), || {
        client.laser(0).scan().is_some()
    });
    drop(feed);
    drop(s);
    wait_for_state(
        &client,
        "the client to notice",
        Duration::from_secs(3),
        |s| *s != ConnectionState::Connected,
    );
    let seq_before = client.laser(0).scan().unwrap().1.seq;

    let s = server(port, Arc::default());
    wait_for_state(&client, "reconnection", Duration::from_secs(5), |s| {
        *s == ConnectionState::Connected
    });
    let _feed = Feeder::start(s.publisher(), addr(&s, "laser:0"));
    wait_for(
        "data again, on the restored subscription",
        Duration::from_secs(3),
        || {
            client
                .laser(0)
                .scan()
                .is_some_and(|(_, st)| st.seq > seq_before)
        },
    );
}

#[test]
fn runtime_data_mode_and_replace_rules_survive_a_server_restart() {
    let s = server(0, Arc::default());
    let port = s.port(0);
    // Connect in PUSH mode with no replace rule; switch both at run time.
    let options = ClientOptions {
        replace_old_data: false,
        ..quick()
    };
    let client = Client::connect("127.0.0.1", port, options).unwrap();
    client.laser(0).subscribe().unwrap();
    client.set_data_mode(DataMode::Pull).unwrap();
    let rule = ReplaceRule::device_data(Interface::LASER, 0, ReplaceAction::Replace);
    client.add_replace_rule(rule).unwrap();
    assert_eq!(client.data_mode(), DataMode::Pull);
    assert_eq!(client.replace_rules(), vec![rule]);

    drop(s);
    wait_for_state(
        &client,
        "the client to notice",
        Duration::from_secs(3),
        |s| *s != ConnectionState::Connected,
    );
    let s = server(port, Arc::default());
    wait_for_state(&client, "reconnection", Duration::from_secs(5), |s| {
        *s == ConnectionState::Connected
    });
    for id in 0..20 {
        s.publisher().publish(addr(&s, "laser:0"), 1, scan(id), 0.0);
    }
    std::thread::sleep(Duration::from_millis(100));
    assert!(
        client.laser(0).scan().is_none(),
        "PULL restored: nothing arrives until asked"
    );
    assert_eq!(
        client.pull().unwrap(),
        1,
        "the restored replace rule left only the newest of 20 scans"
    );
    assert_eq!(client.laser(0).scan().unwrap().0.id, 19);

    // And back to PUSH at run time: data flows unasked.
    client.set_data_mode(DataMode::Push).unwrap();
    s.publisher().publish(addr(&s, "laser:0"), 1, scan(20), 0.0);
    wait_for("pushed data", Duration::from_secs(3), || {
        client
            .laser(0)
            .scan()
            .is_some_and(|(scan, _)| scan.id == 20)
    });
}

#[test]
fn what_is_asked_while_the_server_is_away_holds_once_it_comes() {
    let port = {
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        l.local_addr().unwrap().port()
    };
    let client = Client::spawn("127.0.0.1", port, quick()).unwrap();
    assert_eq!(client.replace_rules(), vec![ReplaceRule::newest_data()]);
    let laser = client.addr(Interface::LASER, 0);
    assert!(matches!(
        client.subscribe_async(laser).wait(Duration::from_secs(5)),
        Err(RequestError::Disconnected(_))
    ));
    assert!(matches!(
        client.set_data_mode(DataMode::Pull),
        Err(RequestError::Disconnected(_))
    ));
    assert_eq!(
        client.data_mode(),
        DataMode::Pull,
        "remembered all the same"
    );

    let s = server(port, Arc::default());
    wait_for_state(&client, "the server", Duration::from_secs(5), |s| {
        *s == ConnectionState::Connected
    });
    for id in 0..5 {
        s.publisher().publish(addr(&s, "laser:0"), 1, scan(id), 0.0);
    }
    assert_eq!(client.pull().unwrap(), 1, "PULL, newest only, subscribed");
    assert_eq!(client.laser(0).scan().unwrap().0.id, 4);
}

#[test]
fn a_quiet_server_is_not_taken_for_a_stalled_one() {
    let s = server(0, Arc::default());
    let options = ClientOptions {
        stall_timeout: Some(Duration::from_millis(100)),
        ..quick()
    };
    let client = Client::connect("127.0.0.1", s.port(0), options).unwrap();
    client.laser(0).subscribe().unwrap();
    // Subscribed, but nothing is published: the server answers the liveness probes only.
    std::thread::sleep(Duration::from_millis(800));
    assert_eq!(client.state(), ConnectionState::Connected);
    assert_eq!(client.last_disconnect(), None);
    assert_eq!(
        client.rejected(),
        0,
        "probe replies are not replies to nothing"
    );
}

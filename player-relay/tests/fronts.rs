//! The relay drives every front alike, through `player_front::Front`: a front written in a
//! few lines — this one counts — hears every robot arrive (by name), each of its messages,
//! each time it leaves, and the stop, once every robot's thread has ended.

mod support;

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use player_proto::RobotId;
use player_proto::capture::Direction;
use player_proto::client::{ConnectionTap, TapEvent};
use player_proto::message::Message;
use player_relay::{Front, Relay, RelayConfig, Route};
use support::{PATIENCE, Robot, scan_id};

/// What the counting front heard.
#[derive(Default)]
struct Heard {
    arrived: Mutex<Vec<String>>,
    opened: AtomicUsize,
    /// The scans' ids, in the order heard, per robot.
    scans: Mutex<Vec<(String, u32)>>,
    left: AtomicUsize,
    stopped: AtomicBool,
    /// Anything heard after the stop.
    late: AtomicUsize,
}

struct Counting(Arc<Heard>);

impl Front for Counting {
    fn name(&self) -> &str {
        "counting"
    }

    fn arrived(&self, robot: &RobotId) -> ConnectionTap {
        self.0.arrived.lock().unwrap().push(robot.to_string());
        let (front, robot) = (self.0.clone(), robot.to_string());
        Arc::new(move |_time, event| {
            if front.stopped.load(Ordering::SeqCst) {
                front.late.fetch_add(1, Ordering::SeqCst);
            }
            match event {
                TapEvent::Opened(_) => {
                    front.opened.fetch_add(1, Ordering::SeqCst);
                }
                TapEvent::Closed(_) => {
                    front.left.fetch_add(1, Ordering::SeqCst);
                }
                TapEvent::Frame {
                    direction: Direction::ServerToClient,
                    header,
                    body,
                } => {
                    let id = Message::decode(*header, body.clone()).ok();
                    if let Some(id) = id.as_ref().and_then(scan_id) {
                        front.scans.lock().unwrap().push((robot.clone(), id));
                    }
                }
                TapEvent::Frame { .. } => {}
            }
        })
    }

    fn stop(&self) {
        self.0.stopped.store(true, Ordering::SeqCst);
    }
}

fn wait_until(what: &str, done: impl Fn() -> bool) {
    let deadline = Instant::now() + PATIENCE;
    while !done() {
        assert!(Instant::now() < deadline, "{what}: not within {PATIENCE:?}");
        std::thread::sleep(Duration::from_millis(5));
    }
}

#[test]
fn a_counting_front_hears_every_robot_message_departure_and_the_stop() {
    const SCANS: u32 = 200;
    let (scout, rover) = (Robot::start(0), Robot::start(0));
    let named = |robot: &Robot, name: &str| Route {
        robot: RobotId::new("127.0.0.1", robot.port()).named(name).unwrap(),
        listen_port: 0,
    };
    let counting = Arc::new(Heard::default());
    let relay = Relay::start(RelayConfig {
        routes: vec![named(&scout, "scout"), named(&rover, "rover")],
        fronts: vec![Arc::new(Counting(counting.clone()))],
        ..RelayConfig::default()
    })
    .expect("the relay starts");
    assert_eq!(*counting.arrived.lock().unwrap(), ["scout", "rover"]);
    wait_until("both connections open", || {
        counting.opened.load(Ordering::SeqCst) == 2
    });
    // The relay subscribes for its fronts once connected: the laser has a subscriber then.
    wait_until("the relay subscribed to the laser", || {
        scout.publish_scan(0) > 0
    });
    wait_until("the first scan heard", || {
        counting
            .scans
            .lock()
            .unwrap()
            .iter()
            .any(|(_, id)| *id == 0)
    });
    counting.scans.lock().unwrap().clear();
    // One at a time, each heard before the next: every message reaches the front.
    for id in 1..=SCANS {
        scout.publish_scan(id);
        wait_until("the scan heard", || {
            counting.scans.lock().unwrap().last() == Some(&("scout".to_string(), id))
        });
    }
    let heard: Vec<u32> = counting.scans.lock().unwrap().iter().map(|s| s.1).collect();
    assert_eq!(
        heard,
        (1..=SCANS).collect::<Vec<_>>(),
        "every scan, once, in order"
    );
    // One robot's server goes: the front hears it leave, and only it.
    rover.server.shutdown();
    wait_until("the rover left", || {
        counting.left.load(Ordering::SeqCst) == 1
    });
    assert!(!counting.stopped.load(Ordering::SeqCst));
    drop(relay);
    assert!(
        counting.stopped.load(Ordering::SeqCst),
        "the stop, once the relay is dropped"
    );
    assert_eq!(
        counting.late.load(Ordering::SeqCst),
        0,
        "nothing heard after the stop"
    );
}

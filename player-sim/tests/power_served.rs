//! r0's power pack in navigation.world, served as `power:0` on port 6666 through the real
//! client over TCP: full at the start with every field valid, burning its rest watts while
//! still, and Stage's cost of motion on top while driving, its charge falling.

mod support;

use std::time::{Duration, Instant};

use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::position2d::{Position2d, Position2dCmdVel};
use player_proto::interfaces::power::{
    MASK_CHARGING, MASK_JOULES, MASK_PERCENT, MASK_VOLTS, MASK_WATTS, Power, PowerData,
};
use player_proto::message::Body;
use player_proto::wire::Interface;
use player_sim::serve::Running;

const SPEEDUP: f64 = 20.0;
/// navigation.world's r0: `kjoules 20 watts 1 mass 10`.
const CAPACITY: f32 = 20_000.0;
const REST_WATTS: f32 = 1.0;
const MASS: f32 = 10.0;
/// Stage's cost of motion, W per kg per m/s.
const WATTS_PER_KG_SPEED: f32 = 10.0;
const SPEED: f64 = 0.3;

fn start() -> (Running, Client) {
    let running = support::serve_navigation(SPEEDUP);
    let port = running.port(6666).unwrap();
    let client = Client::connect("127.0.0.1", port, ClientOptions::default()).unwrap();
    (running, client)
}

/// The first reading after `after` (a sequence number) that `accept`s, its sequence and its
/// simulated time.
fn reading(
    client: &Client,
    after: u64,
    what: &str,
    accept: impl Fn(&PowerData) -> bool,
) -> (PowerData, u64, f64) {
    let deadline = Instant::now() + Duration::from_secs(20);
    loop {
        let got = client
            .latest(
                client.addr(Interface::POWER, 0),
                Power::DATA_STATE.subtype(),
            )
            .filter(|s| s.seq > after);
        if let Some(s) = got {
            let Body::Power(Power::State(data)) = s.message.body else {
                panic!("not a power state: {:?}", s.message.body);
            };
            if accept(&data) {
                return (data, s.seq, s.server_time);
            }
        }
        assert!(Instant::now() < deadline, "timed out waiting for {what}");
        std::thread::sleep(Duration::from_millis(2));
    }
}

#[test]
fn the_pack_drains_at_rest_and_faster_while_driving() {
    let (_running, client) = start();
    let power = client.addr(Interface::POWER, 0);
    assert_eq!(client.subscribe(power).unwrap(), "stage");
    let (still, seq, time) = reading(&client, 0, "a reading at rest", |_| true);
    assert_eq!(
        still.valid,
        MASK_VOLTS | MASK_WATTS | MASK_JOULES | MASK_PERCENT | MASK_CHARGING
    );
    assert_eq!(still.watts, -REST_WATTS, "Player's sign: negative consumes");
    // Burnt at rest since the start: however long the client took to subscribe (at 20x, a
    // busy machine's 100 ms are 2 simulated seconds).
    let burnt = CAPACITY - still.joules;
    let expected = REST_WATTS * time as f32;
    assert!(
        burnt > 0.0 && (burnt - expected).abs() <= REST_WATTS * 0.11,
        "{burnt} J burnt in {time} s at rest"
    );
    assert!((still.percent - still.joules / CAPACITY * 100.0).abs() < 1e-3);
    assert_eq!(still.charging, 0);

    let position = client.addr(Interface::POSITION2D, 0);
    client.subscribe(position).unwrap();
    client.command(
        position,
        Body::Position2d(Position2d::Velocity(Position2dCmdVel {
            vel: Pose2d::new(SPEED, 0.0, 0.0),
            state: 1,
        })),
    );
    let driving_watts = REST_WATTS + SPEED as f32 * WATTS_PER_KG_SPEED * MASS;
    let (driving, seq, _) = reading(&client, seq, "the cost of driving", |d| {
        (d.watts + driving_watts).abs() < 1e-3
    });
    let (later, _, _) = reading(&client, seq, "a later reading", |d| {
        d.joules < driving.joules
    });
    assert!(later.joules < still.joules - 1.0, "{later:?} vs {still:?}");
    assert!(later.percent < still.percent);
}

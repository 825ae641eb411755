//! `pv3d --world stage-worlds/navigation.world` end to end: the world is served with its
//! navigation half (navigation-nav.cfg, found beside it), the composition is pointed at the
//! navigation port too, and a goal sent to wavefront over TCP brings r0 there.

use std::path::Path;
use std::time::{Duration, Instant};

use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::planner::{Planner, PlannerCmd};
use player_proto::message::Body;
use player_proto::wire::Interface;
use player_sim::serve::ServeOptions;
use pv3d::composition::{Composition, ParserRegistry};
use pv3d::embedded_world::serve_world;

/// The port navigation-nav.cfg serves map, localize and planner on.
const NAV_PORT: u16 = 6665;
/// Simulated seconds per real second: the crossing takes about 40 simulated seconds.
const SPEEDUP: f64 = 20.0;
/// Across the doorway and round the far room's wall, facing up (clear of the pucks).
const GOAL: Pose2d = Pose2d::new(3.5, 4.5, std::f64::consts::FRAC_PI_2);
/// wavefront's `distance_epsilon` in navigation-nav.cfg.
const ARRIVED_WITHIN: f64 = 0.5;

#[test]
fn a_goal_sent_to_the_served_navigation_world_brings_the_robot_there() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let world = root.join("stage-worlds/navigation.world");
    let mut composition = Composition::load_files(
        &[pv3d::demo::world_composition_file(&world)],
        &ParserRegistry::standard(),
    )
    .unwrap();
    let options = ServeOptions {
        speedup: SPEEDUP,
        ..ServeOptions::default()
    };
    let running = serve_world(&world, &mut composition, options).unwrap();
    let port = running
        .port(NAV_PORT)
        .expect("the navigation half is served");
    assert!(
        composition.clients.iter().any(|c| c.port == port),
        "the viewer is pointed at the navigation port"
    );

    let client = Client::connect("127.0.0.1", port, ClientOptions::default()).unwrap();
    let served: Vec<Interface> = client.devices().iter().map(|d| d.addr.interf).collect();
    for wanted in [Interface::MAP, Interface::LOCALIZE, Interface::PLANNER] {
        assert!(served.contains(&wanted), "{wanted} not in {served:?}");
    }
    let planner = client.addr(Interface::PLANNER, 0);
    assert_eq!(client.subscribe(planner).unwrap(), "wavefront");
    client.command(
        planner,
        Body::Planner(Planner::Goal(PlannerCmd { goal: GOAL })),
    );

    let deadline = Instant::now() + Duration::from_secs(30);
    let arrived = loop {
        let state = client
            .latest(planner, Planner::DATA_STATE.subtype())
            .and_then(|s| match &s.message.body {
                Body::Planner(Planner::State(state)) => Some(*state),
                _ => None,
            });
        if let Some(state) = state.filter(|s| s.is_done()) {
            break state;
        }
        assert!(Instant::now() < deadline, "r0 did not arrive: {state:?}");
        std::thread::sleep(Duration::from_millis(10));
    };
    assert!(arrived.is_valid());
    let r0 = running.sim.lock().unwrap().robots[0].pose;
    let off = (r0.x - GOAL.px).hypot(r0.y - GOAL.py);
    assert!(off < ARRIVED_WITHIN, "r0 at {r0:?}, {off} m from the goal");
}

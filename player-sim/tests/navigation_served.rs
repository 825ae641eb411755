//! navigation.world's navigation half through the real client over TCP, compared with what
//! Player's own amcl and wavefront sent in `captures/nav/`: hypotheses on subscribing and
//! after a set pose, stamped with the server's clock while Stage's data carry the
//! simulation's; the planner's state before a goal, with its waypoint and count while driving,
//! and without them once done; enable 0 stops the robot.

mod support;

use std::time::Duration;

use player_proto::client::{Client, ClientOptions, Stamped};
use player_proto::interfaces::common::{BoolValue, Pose2d};
use player_proto::interfaces::localize::{Localize, LocalizeData, LocalizeSetPose};
use player_proto::interfaces::planner::{Planner, PlannerCmd, PlannerData};
use player_proto::interfaces::position2d::Position2d;
use player_proto::message::Body;
use player_proto::wire::Interface;
use player_sim::serve::Running;
use support::wait_for;

/// How long a test waits for what the server sends, in real time.
const WAIT: Duration = Duration::from_secs(20);

/// Simulated seconds per real second: a crossing of the floor takes a few real seconds.
const SPEEDUP: f64 = 20.0;
/// Any wall-clock stamp is later than this (2001), any simulated one of a test far earlier.
const WALL_CLOCK_AFTER: f64 = 1e9;

fn start() -> (Running, Client) {
    let running = support::serve_navigation(SPEEDUP);
    let port = running.port(6665).unwrap();
    let client = Client::connect("127.0.0.1", port, ClientOptions::default()).unwrap();
    (running, client)
}

/// The newest message of `subtype` newer than `after` (a sequence number).
fn newer(client: &Client, interf: Interface, subtype: u8, after: u64) -> Option<Stamped> {
    client
        .latest(client.addr(interf, 0), subtype)
        .filter(|s| s.seq > after)
}

fn hypotheses(stamped: &Stamped) -> LocalizeData {
    match &stamped.message.body {
        Body::Localize(Localize::Hypotheses(h)) => h.clone(),
        other => panic!("not hypotheses: {other:?}"),
    }
}

fn planner_state(stamped: &Stamped) -> PlannerData {
    match &stamped.message.body {
        Body::Planner(Planner::State(s)) => *s,
        other => panic!("not a planner state: {other:?}"),
    }
}

#[test]
fn set_pose_moves_the_estimate_and_particles_surround_it() {
    let (_running, client) = start();
    let localize = client.addr(Interface::LOCALIZE, 0);
    let odometry = client.addr(Interface::POSITION2D, 0);
    assert_eq!(client.subscribe(odometry).unwrap(), "passthrough");
    assert_eq!(client.subscribe(localize).unwrap(), "amcl");
    let first = wait_for("hypotheses on subscribing", WAIT, || {
        newer(
            &client,
            Interface::LOCALIZE,
            Localize::DATA_HYPOTHS.subtype(),
            0,
        )
    });
    let h = hypotheses(&first);
    assert_eq!((h.hypoths.len(), h.pending_count), (1, 0));
    let best = h.best().unwrap();
    assert_eq!(best.alpha, 1.0);
    assert!((best.mean.px + 6.5).abs() < 1e-9 && (best.mean.py + 4.5).abs() < 1e-9);
    assert!(best.cov[0] > 0.0 && best.cov[0] < 0.01);
    // amcl stamps with the server's clock, Stage's odometry with the simulation's.
    assert!(first.server_time > WALL_CLOCK_AFTER);
    let (_, odo) = wait_for("odometry", WAIT, || {
        client
            .latest(odometry, Position2d::DATA_STATE.subtype())
            .map(|s| ((), s))
    });
    assert!(odo.server_time < WALL_CLOCK_AFTER);

    // Re-initialise the estimate elsewhere, as a user placing the robot on the map does.
    let told = Pose2d::new(2.0, 1.0, 1.0);
    let set = LocalizeSetPose {
        mean: told,
        cov: [0.05, 0.05, 0.05, 0.0, 0.0, 0.0],
    };
    let reply = client.request(
        localize,
        Localize::REQ_SET_POSE.subtype(),
        Body::Localize(Localize::SetPose(set)),
    );
    assert!(reply.is_ok(), "{reply:?}");
    let moved = wait_for("hypotheses after set pose", WAIT, || {
        newer(
            &client,
            Interface::LOCALIZE,
            Localize::DATA_HYPOTHS.subtype(),
            first.seq,
        )
    });
    let mean = hypotheses(&moved).best().unwrap().mean;
    assert!((mean.px - 2.0).abs() < 1e-9 && (mean.py - 1.0).abs() < 1e-9);
    assert!((mean.pa - 1.0).abs() < 1e-9);

    // Driving on: the estimate follows, one metre ahead along the told heading.
    client.command(
        odometry,
        Body::Position2d(Position2d::Velocity(
            player_proto::interfaces::position2d::Position2dCmdVel {
                vel: Pose2d::new(0.5, 0.0, 0.0),
                state: 1,
            },
        )),
    );
    let ahead = wait_for("the estimate a metre on", WAIT, || {
        newer(
            &client,
            Interface::LOCALIZE,
            Localize::DATA_HYPOTHS.subtype(),
            moved.seq,
        )
        .map(|s| hypotheses(&s).best().unwrap().mean)
        .filter(|m| (m.px - 2.0).hypot(m.py - 1.0) > 1.0)
    });
    let along = (ahead.py - 1.0).atan2(ahead.px - 2.0);
    assert!((along - 1.0).abs() < 0.02, "moved along {along}");

    let particles = client
        .request(localize, Localize::REQ_GET_PARTICLES.subtype(), Body::Empty)
        .unwrap();
    let Body::Localize(Localize::Particles(cloud)) = &particles.body else {
        panic!("{:?}", particles.body);
    };
    assert_eq!(cloud.particles.len(), 100, "pf_min_samples");
    assert_eq!(cloud.mean.pa, 0.0, "amcl leaves the mean's heading 0");
    assert!(
        cloud
            .particles
            .iter()
            .all(|p| { (p.pose.px - cloud.mean.px).hypot(p.pose.py - cloud.mean.py) < 0.1 })
    );
}

#[test]
fn a_goal_is_planned_driven_to_and_reported_as_wavefront_does() {
    let (running, client) = start();
    // r1 wanders along r0's route: two robots meeting head on can wedge each other (each
    // turning into the other, both stalled), which whether they do depends on every
    // centimetre of r1's path. This test is about the planner: r1 stands still.
    {
        let mut sim = running.sim.lock().unwrap();
        let r1 = sim.robot_index("r1").expect("r1");
        sim.world.robots[r1].controller = None;
        sim.robots[r1].command = player_sim::sim::Command::Velocity {
            vx: 0.0,
            vy: 0.0,
            va: 0.0,
        };
    }
    let planner = client.addr(Interface::PLANNER, 0);
    assert_eq!(client.subscribe(planner).unwrap(), "wavefront");
    let state = Planner::DATA_STATE.subtype();
    let before = wait_for("a state before any goal", WAIT, || {
        newer(&client, Interface::PLANNER, state, 0)
    });
    let idle = planner_state(&before);
    assert_eq!((idle.valid, idle.done, idle.waypoints_count), (0, 0, 0));
    assert_eq!(idle.goal, Pose2d::default());
    assert!(
        (idle.pos.px + 6.5).abs() < 1e-6,
        "the amcl pose: {:?}",
        idle.pos
    );
    assert!(before.server_time > WALL_CLOCK_AFTER);
    let none = client
        .request(planner, Planner::REQ_GET_WAYPOINTS.subtype(), Body::Empty)
        .unwrap();
    let Body::Planner(Planner::Waypoints(none)) = none.body else {
        panic!("no waypoints answer");
    };
    assert!(none.waypoints.is_empty() && none.waypoints_distance == 0.0);

    let goal = Pose2d::new(3.5, 4.5, std::f64::consts::FRAC_PI_2);
    client.command(planner, Body::Planner(Planner::Goal(PlannerCmd { goal })));
    let driving = wait_for("a valid plan", WAIT, || {
        newer(&client, Interface::PLANNER, state, before.seq)
            .filter(|s| planner_state(s).is_valid())
    });
    let s = planner_state(&driving);
    assert_eq!((s.done, s.goal), (0, goal));
    assert!(s.waypoints_count >= 3 && s.waypoint_idx >= 1);
    assert_eq!(
        s.waypoint.pa, goal.pa,
        "a waypoint carries the goal's heading"
    );
    let plan = client
        .request(planner, Planner::REQ_GET_WAYPOINTS.subtype(), Body::Empty)
        .unwrap();
    let Body::Planner(Planner::Waypoints(plan)) = plan.body else {
        panic!("no waypoints answer");
    };
    assert_eq!(plan.waypoints.len(), s.waypoints_count as usize);

    // Disabled, the robot stops (the state keeps coming); enabled, it goes on.
    let off = client.request(
        planner,
        Planner::REQ_ENABLE.subtype(),
        Body::Planner(Planner::Enable(BoolValue::new(false))),
    );
    assert!(off.is_ok());
    let paused = wait_for("a state after disabling", WAIT, || {
        newer(&client, Interface::PLANNER, state, driving.seq + 2)
    });
    let a = planner_state(&paused).pos;
    let later = wait_for("another state", WAIT, || {
        newer(&client, Interface::PLANNER, state, paused.seq + 3)
    });
    assert_eq!(
        planner_state(&later).pos,
        a,
        "a disabled planner does not drive"
    );
    client
        .request(
            planner,
            Planner::REQ_ENABLE.subtype(),
            Body::Planner(Planner::Enable(BoolValue::new(true))),
        )
        .unwrap();

    let done = wait_for("the goal reached", WAIT, || {
        newer(&client, Interface::PLANNER, state, later.seq).filter(|s| planner_state(s).is_done())
    });
    let d = planner_state(&done);
    assert_eq!(
        (d.valid, d.done, d.waypoint_idx, d.waypoints_count),
        (1, 1, 0, 0)
    );
    assert_eq!(d.waypoint, Pose2d::default());
    assert!(
        (d.pos.px - goal.px).hypot(d.pos.py - goal.py) < 0.5,
        "{:?}",
        d.pos
    );
    let after = client
        .request(planner, Planner::REQ_GET_WAYPOINTS.subtype(), Body::Empty)
        .unwrap();
    let Body::Planner(Planner::Waypoints(after)) = after.body else {
        panic!("no waypoints answer");
    };
    assert_eq!(after, plan, "the plan stays once done");
}

#[test]
fn an_unreachable_goal_is_not_valid() {
    let (_running, client) = start();
    let planner = client.addr(Interface::PLANNER, 0);
    client.subscribe(planner).unwrap();
    let state = Planner::DATA_STATE.subtype();
    let goal = Pose2d::new(-7.95, 0.0, 0.0);
    client.command(planner, Body::Planner(Planner::Goal(PlannerCmd { goal })));
    let told = wait_for("the goal in the state", WAIT, || {
        newer(&client, Interface::PLANNER, state, 0).filter(|s| planner_state(s).goal == goal)
    });
    let s = planner_state(&told);
    assert_eq!((s.valid, s.done, s.waypoints_count), (0, 0, 0));
}

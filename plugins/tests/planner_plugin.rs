//! The planner plugin fed known states: a new plan makes it ask for the way-points and draw
//! the path through them; progress along the same plan asks nothing; as the active handler a
//! ground click becomes the planner's goal command (the chain stops there, so no robot drives
//! straight to it).

mod support;

use framework::PluginConfig;
use framework::config::{DeviceRef, Param};
use framework::plugin::{Handled, InputEvent, Plugin};
use glam::Vec3;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::planner::{Planner, PlannerData, PlannerWaypoints};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::{Harness, harness};

fn addr() -> DevAddr {
    "planner:0".parse().unwrap()
}

fn config(params: Vec<Param>) -> PluginConfig {
    PluginConfig {
        library: "libpv3d_planner".into(),
        id: "wavefront".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: addr(),
            driver: "wavefront".into(),
        }),
        params,
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    }
}

fn feed(h: &Harness, waypoint_idx: i32) {
    let state = PlannerData {
        valid: 1,
        pos: Pose2d::new(0.0, 0.0, 0.0),
        goal: Pose2d::new(4.0, 2.0, 0.0),
        waypoint_idx,
        waypoints_count: 3,
        ..PlannerData::default()
    };
    h.device
        .push(Message::typed(addr(), MsgType::Data, Planner::State(state)));
}

fn waypoint_requests(h: &Harness) -> usize {
    h.device
        .requests
        .lock()
        .unwrap()
        .iter()
        .filter(|(k, _)| *k == Planner::REQ_GET_WAYPOINTS.kind())
        .count()
}

fn make(h: &mut Harness) -> Box<dyn Plugin> {
    h.make(config(vec![])).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_new_plan_fetches_its_waypoints_and_draws_the_path_through_them() {
    let mut h = harness();
    let mut plugin = make(&mut h);
    feed(&h, 0);
    plugin.run(&mut h.ctx());
    assert_eq!(waypoint_requests(&h), 1);
    let waypoints = PlannerWaypoints {
        waypoints: vec![
            Pose2d::new(1.0, 0.0, 0.0),
            Pose2d::new(2.0, 2.0, 0.0),
            Pose2d::new(4.0, 2.0, 0.0),
        ],
        ..PlannerWaypoints::default()
    };
    let reply = Message::typed(addr(), MsgType::Ack, Planner::Waypoints(waypoints));
    h.device
        .answer_later(Planner::REQ_GET_WAYPOINTS.kind(), Ok(reply));
    assert!(h.run_changes_scene(plugin.as_mut()), "the way-points drawn");
    let path = &h.scene.get(plugin.node().unwrap()).unwrap().geometry;
    assert_eq!(path.points.len(), 3, "one dot per way-point");
    let through = |x: f32, y: f32| {
        path.lines
            .iter()
            .any(|v| (v.pos.truncate() - glam::Vec2::new(x, y)).length() < 1e-5)
    };
    assert!(through(0.0, 0.0) && through(2.0, 2.0) && through(4.0, 2.0));
    assert!(!path.triangles.is_empty(), "the goal flag");

    // Progress along the same plan: drawn, not fetched again.
    feed(&h, 1);
    plugin.run(&mut h.ctx());
    assert_eq!(waypoint_requests(&h), 1);
}

#[test]
fn as_the_active_handler_a_ground_click_is_the_planners_goal() {
    let mut h = harness();
    let mut plugin = make(&mut h);
    let click = InputEvent::GroundClicked(Vec3::new(3.0, -1.0, 0.0));
    assert_eq!(plugin.on_event(&click, &mut h.ctx()), Handled::No);
    assert!(h.device.commands.lock().unwrap().is_empty());

    assert!(plugin.can_be_active());
    plugin.on_event(&InputEvent::Activated(true), &mut h.ctx());
    assert_eq!(plugin.on_event(&click, &mut h.ctx()), Handled::Yes);
    // A drag: pressed at (1, 1), pulled towards −x: the goal faces back.
    for at in [Vec3::new(1.0, 1.0, 0.0), Vec3::new(0.5, 1.0, 0.0)] {
        plugin.on_event(&InputEvent::TargetDragged(at), &mut h.ctx());
    }
    let release = InputEvent::GroundClicked(Vec3::new(0.0, 1.0, 0.0));
    assert_eq!(plugin.on_event(&release, &mut h.ctx()), Handled::Yes);

    let commands = h.device.commands.lock().unwrap();
    let goals: Vec<Pose2d> = commands
        .iter()
        .map(|body| {
            Planner::CMD_GOAL
                .body_of(body)
                .expect("a goal command")
                .goal
        })
        .collect();
    assert_eq!(goals.len(), 2);
    assert_eq!((goals[0].px, goals[0].py), (3.0, -1.0));
    assert_eq!((goals[1].px, goals[1].py), (1.0, 1.0));
    assert!((goals[1].pa.abs() - std::f64::consts::PI).abs() < 1e-6);
}

#[test]
fn disabling_asks_the_planner_to_stop() {
    let mut h = harness();
    let mut plugin = make(&mut h);
    plugin.run_service("Disable", &mut h.ctx());
    let requests = h.device.requests.lock().unwrap();
    let (kind, body) = requests.last().expect("a request");
    assert_eq!(*kind, Planner::REQ_ENABLE.kind());
    assert_eq!(Planner::REQ_ENABLE.body_of(body).unwrap().state, 0);
    assert_eq!(plugin.services()[0].name, "Enable");
}

#[test]
fn a_bad_colour_names_the_parameter() {
    let mut h = harness();
    let error = h
        .make(config(vec![Param::new("color", "plaid")]))
        .err()
        .expect("refused");
    assert!(error.to_string().contains("color"), "{error}");
}

//! A robot answers queries: "where are you", "go to" a point or an object, "follow", "stop" —
//! and drives as it would after a click, holding at the edge of a zone it avoids.

mod support;

use framework::PluginConfig;
use framework::device::RecordingDevice;
use framework::query::{BAD_ARGUMENTS, FAILED, Query, Target, XmlElement};
use framework::scene::Object3D;
use glam::Vec3;
use player_proto::interfaces::position2d::{Position2d, Position2dData};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::{harness, position2d};

fn config() -> PluginConfig {
    position2d::config("robot1")
}

fn odometry(device: &RecordingDevice, x: f64, y: f64) {
    position2d::odometry(device, x, y, 0.0);
}

fn last_velocity(device: &RecordingDevice) -> Option<(f64, f64)> {
    position2d::velocities(device).last().copied()
}

/// robot1, its odometry at the origin taken.
fn robot_at_origin(w: &mut support::Harness) -> Box<dyn framework::Plugin> {
    let mut robot = w.make(config()).unwrap();
    odometry(&w.device, 0.0, 0.0);
    robot.run(&mut w.ctx());
    robot
}

/// An object called `name`, tagged `tag`, at (`x`, 0).
fn place(w: &mut support::Harness, name: &str, tag: &str, x: f32) {
    let mut object = Object3D::new(name);
    object.tags = vec![tag.into()];
    object.transform = glam::Affine3A::from_translation(Vec3::new(x, 0.0, 0.0));
    w.scene.add(object);
}

fn ask(name: &str) -> Query {
    Query::new(Target::Named("robot1".into()), name)
}

#[test]
fn a_robot_says_where_it_is_and_goes_where_it_is_told() {
    let mut w = harness();
    let mut robot = w.make(config()).unwrap();
    odometry(&w.device, 1.0, 2.0);
    robot.run(&mut w.ctx());

    let here = robot.answer(&ask("where are you"), &mut w.ctx()).unwrap();
    assert!(here.is_done());
    assert_eq!(
        (here.body.number("x"), here.body.number("y")),
        (Ok(1.0), Ok(2.0))
    );

    let go = ask("go to").with_child(XmlElement::new("point").with_attr("x", 4).with_attr("y", 2));
    let reply = robot.answer(&go, &mut w.ctx()).unwrap();
    assert!(reply.is_done(), "{reply:?}");
    assert_eq!(reply.body.child("goal").unwrap().number("x"), Ok(4.0));
    robot.run(&mut w.ctx());
    let (speed, _) = last_velocity(&w.device).expect("a velocity command");
    assert!(speed > 0.0, "drives towards the goal: {speed}");

    let stop = robot.answer(&ask("stop"), &mut w.ctx()).unwrap();
    assert!(stop.is_done() && stop.body.child("goal").is_none());
    assert_eq!(last_velocity(&w.device), Some((0.0, 0.0)));

    let bad = robot
        .answer(&ask("go to").with_attr("x", 1), &mut w.ctx())
        .unwrap();
    assert_eq!(bad.error, BAD_ARGUMENTS);
    assert!(
        robot.answer(&ask("sing"), &mut w.ctx()).is_none(),
        "not a robot's query"
    );
}

#[test]
fn a_robot_follows_the_nearest_object_with_a_tag() {
    let mut w = harness();
    let mut robot = robot_at_origin(&mut w);
    let follow = ask("follow").with_attr("tag", "person");
    let nobody = robot.answer(&follow, &mut w.ctx()).unwrap();
    assert_eq!(nobody.error, FAILED);
    assert!(nobody.body.text.contains("person"), "{:?}", nobody.body);

    place(&mut w, "person far", "person", 9.0);
    place(&mut w, "person near", "person", 3.0);
    let reply = robot.answer(&follow, &mut w.ctx()).unwrap();
    assert!(reply.is_done());
    assert_eq!(reply.body.attr("name"), Some("person near"));
}

#[test]
fn a_robots_condition_is_on_its_node_as_tags() {
    let mut w = harness();
    let mut robot = w.make(config()).unwrap();
    let tags = |w: &support::Harness, robot: &dyn framework::Plugin| {
        w.scene.get(robot.node().unwrap()).unwrap().tags.clone()
    };
    let addr: DevAddr = "position2d:0".parse().unwrap();
    let stalled = Position2dData {
        stall: 1,
        ..Position2dData::default()
    };
    w.device.push(Message::typed(
        addr,
        MsgType::Data,
        Position2d::State(stalled),
    ));
    robot.run(&mut w.ctx());
    assert!(tags(&w, robot.as_ref()).contains(&"stalled".to_string()));
    let reply = robot.answer(&ask("where are you"), &mut w.ctx()).unwrap();
    assert_eq!(reply.body.attr("stalled"), Some("true"));

    odometry(&w.device, 0.0, 0.0);
    robot.run(&mut w.ctx());
    assert!(!tags(&w, robot.as_ref()).contains(&"stalled".to_string()));
    assert!(!tags(&w, robot.as_ref()).contains(&"stale".to_string()));
    w.now += plugins::position2d::STALE_AFTER * 2;
    robot.run(&mut w.ctx());
    assert!(
        tags(&w, robot.as_ref()).contains(&"stale".to_string()),
        "no data for a while"
    );
}

#[test]
fn a_robot_asks_about_its_goal_and_gives_up_one_in_keep_out() {
    use framework::query::Reply;
    let mut w = harness();
    let mut robot = robot_at_origin(&mut w);
    let go = |x: i32| {
        ask("go to").with_child(XmlElement::new("point").with_attr("x", x).with_attr("y", 0))
    };
    let mut outbox = Vec::new();
    robot
        .answer(&go(3), &mut w.ctx().with_outbox(&mut outbox))
        .unwrap();
    let names: Vec<&str> = outbox.iter().map(|q| q.name.as_str()).collect();
    assert_eq!(names, ["is point free", "which zone"]);
    assert_eq!(outbox[1].point(), Ok((3.0, 0.0)));

    let free = Reply::done(XmlElement::new("cell").with_attr("state", "free"));
    robot.on_reply(&outbox[0], &Ok(free), &mut w.ctx());
    let nowhere = Reply::done(XmlElement::new("zones"));
    robot.on_reply(&outbox[1], &Ok(nowhere), &mut w.ctx());
    let here = robot.answer(&ask("where are you"), &mut w.ctx()).unwrap();
    assert!(
        here.body.child("goal").is_some(),
        "a free point: still going"
    );

    let keep_out = Reply::done(
        XmlElement::new("zones").with_child(XmlElement::new("zone").with_attr("name", "keep out")),
    );
    robot.on_reply(&outbox[1], &Ok(keep_out), &mut w.ctx());
    let here = robot.answer(&ask("where are you"), &mut w.ctx()).unwrap();
    assert!(here.body.child("goal").is_none(), "given up: {here:?}");
    assert_eq!(last_velocity(&w.device), Some((0.0, 0.0)));

    // A late answer about an old goal changes nothing.
    robot.answer(&go(5), &mut w.ctx()).unwrap();
    let wall = Reply::done(XmlElement::new("cell").with_attr("state", "occupied"));
    robot.on_reply(&outbox[0], &Ok(wall), &mut w.ctx());
    let here = robot.answer(&ask("where are you"), &mut w.ctx()).unwrap();
    assert_eq!(here.body.child("goal").unwrap().number("x"), Ok(5.0));
}

#[test]
fn a_robot_goes_up_to_or_follows_an_object_named_by_name() {
    let mut w = harness();
    let mut robot = robot_at_origin(&mut w);
    place(&mut w, "robot2", "robot", 4.0);

    let go = robot
        .answer(&ask("go to").with_attr("object", "robot2"), &mut w.ctx())
        .unwrap();
    assert!(go.is_done(), "{go:?}");
    assert_eq!(go.body.name, "going to");
    let here = robot.answer(&ask("where are you"), &mut w.ctx()).unwrap();
    let goal_x = here.body.child("goal").unwrap().number("x").unwrap();
    assert!(
        (goal_x - 3.2).abs() < 1e-3,
        "stops followDistance (0.8 m) short: {goal_x}"
    );

    let follow = robot
        .answer(&ask("follow").with_attr("object", "robot2"), &mut w.ctx())
        .unwrap();
    assert_eq!(follow.body.attr("name"), Some("robot2"));
    let ghost = robot
        .answer(&ask("follow").with_attr("object", "robot9"), &mut w.ctx())
        .unwrap();
    assert_eq!(ghost.error, FAILED);
    assert!(ghost.body.text.contains("robot9"), "{:?}", ghost.body);
    let nothing = robot.answer(&ask("follow"), &mut w.ctx()).unwrap();
    assert_eq!(nothing.error, BAD_ARGUMENTS);
}

#[test]
fn a_robot_holds_still_while_the_way_ahead_enters_keep_out() {
    use framework::query::Reply;
    let zones = |names: &[&str]| {
        let mut body = XmlElement::new("zones");
        for name in names {
            body.children
                .push(XmlElement::new("zone").with_attr("name", *name));
        }
        Ok(Reply::done(body))
    };
    let mut w = harness();
    let mut robot = robot_at_origin(&mut w);
    place(&mut w, "person 1", "person", 3.0);
    robot
        .answer(&ask("follow").with_attr("tag", "person"), &mut w.ctx())
        .unwrap();

    let mut outbox = Vec::new();
    robot.run(&mut w.ctx().with_outbox(&mut outbox));
    let (speed, _) = last_velocity(&w.device).expect("driving");
    assert!(speed > 0.0);
    let about: Vec<_> = outbox.iter().filter_map(|q| q.body.attr("about")).collect();
    assert_eq!(about, ["robot", "way ahead"], "{outbox:?}");
    let ahead = outbox[1].point().unwrap();
    assert!(
        (ahead.0 - f64::from(plugins::position2d::LOOKAHEAD)).abs() < 1e-4,
        "{ahead:?}"
    );
    robot.on_reply(&outbox[0], &zones(&[]), &mut w.ctx());
    robot.on_reply(&outbox[1], &zones(&["keep out"]), &mut w.ctx());

    w.now += std::time::Duration::from_millis(50);
    robot.run(&mut w.ctx());
    assert_eq!(
        last_velocity(&w.device),
        Some((0.0, 0.0)),
        "held at the edge"
    );
    let here = robot.answer(&ask("where are you"), &mut w.ctx()).unwrap();
    assert!(here.body.child("following").is_some(), "still following");
    assert_eq!(
        here.body.child("waiting").and_then(|z| z.attr("zone")),
        Some("keep out")
    );

    // The way leads elsewhere: it drives again.
    robot.on_reply(&outbox[1], &zones(&[]), &mut w.ctx());
    w.now += std::time::Duration::from_millis(200);
    robot.run(&mut w.ctx());
    let (speed, _) = last_velocity(&w.device).unwrap();
    assert!(speed > 0.0, "on its way again: {speed}");
}

//! A robot's actions on clicked objects, fed by hand: "Go to" and "Follow" a marker that the
//! fiducial finder re-creates every scan, in velocity and in position mode.

mod support;

use std::time::Duration;

use framework::action::ObjectRef;
use framework::config::Param;
use framework::plugin::InputEvent;
use glam::Vec3;
use support::position2d::{config, marker, odometry, velocities, waypoints, world, world_with};

#[test]
fn go_to_and_follow_a_marker_that_is_re_created_every_scan() {
    let (mut w, mut plugin) = world();
    odometry(&w.device, 0.0, 0.0, 0.0);
    plugin.run(&mut w.ctx());
    let seen = marker(&mut w.scene, 7, 3.0, 0.0);
    let target = ObjectRef::of(&w.scene, seen).unwrap();
    let names: Vec<&str> = plugin.actions_on(&target).iter().map(|a| a.name).collect();
    assert_eq!(names, ["Go to", "Follow"]);
    let own = ObjectRef::of(&w.scene, plugin.node().unwrap()).unwrap();
    assert!(
        plugin.actions_on(&own).is_empty(),
        "nothing to do with itself"
    );

    // Go to: drives to 0.8 m short of the marker, then stops there.
    plugin.run_action("Go to", &target, &mut w.ctx());
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert!(velocities(&w.device).last().unwrap().0 > 0.4);
    odometry(&w.device, 2.19, 0.0, 0.0);
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(
        *velocities(&w.device).last().unwrap(),
        (0.0, 0.0),
        "next to it"
    );

    // Follow: the marker is re-created elsewhere; the robot turns and heads for it.
    plugin.run_action("Follow", &target, &mut w.ctx());
    w.scene.remove(seen);
    marker(&mut w.scene, 8, 2.5, -2.0);
    marker(&mut w.scene, 7, 2.2, 3.0);
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    let (_, turn) = *velocities(&w.device).last().unwrap();
    assert!(turn > 0.5, "turning left, towards marker 7 (not 8): {turn}");
    // Near enough: it holds still, but keeps following.
    odometry(&w.device, 2.2, 2.3, 1.57);
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(*velocities(&w.device).last().unwrap(), (0.0, 0.0));
    let held = velocities(&w.device).len();
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(
        velocities(&w.device).len(),
        held,
        "holding: no repeated commands"
    );
    // The person walks on; the robot goes after them, until stopped.
    let walked = w.scene.iter().find(|(_, o)| o.has_tag("id:7")).unwrap().0;
    w.scene.get_mut(walked).unwrap().transform =
        glam::Affine3A::from_translation(Vec3::new(2.2, 5.0, 0.0));
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert!(velocities(&w.device).last().unwrap().0 > 0.3, "after them");
    plugin.on_event(&InputEvent::StopAll, &mut w.ctx());
    assert_eq!(*velocities(&w.device).last().unwrap(), (0.0, 0.0));
    let stopped = velocities(&w.device).len();
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(velocities(&w.device).len(), stopped, "stopped following");
}

#[test]
fn following_in_position_mode_sends_a_new_waypoint_only_when_the_object_moved() {
    let mut c = config("r0");
    c.params.push(Param::new("mode", "position"));
    c.params.push(Param::new("followDistance", "1"));
    let (mut w, mut plugin) = world_with(c);
    odometry(&w.device, 0.0, 0.0, 0.0);
    plugin.run(&mut w.ctx());
    let seen = marker(&mut w.scene, 7, 4.0, 0.0);
    let target = ObjectRef::of(&w.scene, seen).unwrap();
    plugin.run_action("Follow", &target, &mut w.ctx());
    for _ in 0..3 {
        w.now += Duration::from_millis(200);
        plugin.run(&mut w.ctx());
    }
    let sent = waypoints(&w.device);
    assert_eq!(sent.len(), 1, "{sent:?}");
    assert!(
        (sent[0].0 - 3.0).abs() < 1e-5 && sent[0].1.abs() < 1e-5,
        "1 m short"
    );
    // A small step of the person: no new way-point; a real one: a new way-point.
    w.scene.get_mut(seen).unwrap().transform =
        glam::Affine3A::from_translation(Vec3::new(4.05, 0.0, 0.0));
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(waypoints(&w.device).len(), 1);
    w.scene.get_mut(seen).unwrap().transform =
        glam::Affine3A::from_translation(Vec3::new(4.0, 2.0, 0.0));
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    let sent = waypoints(&w.device);
    assert_eq!(sent.len(), 2);
    let (x, y, a) = sent[1];
    let expected = Vec3::new(4.0, 2.0, 0.0) - Vec3::new(4.0, 2.0, 0.0).normalize();
    assert!((x - f64::from(expected.x)).abs() < 1e-4 && (y - f64::from(expected.y)).abs() < 1e-4);
    assert!(
        (a - (2.0f64).atan2(4.0)).abs() < 1e-4,
        "facing the person: {a}"
    );
    // Arrived within the distance: a zero velocity, and no more way-points.
    odometry(&w.device, expected.x.into(), expected.y.into(), a);
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(velocities(&w.device), vec![(0.0, 0.0)]);
    assert_eq!(waypoints(&w.device).len(), 2);
}

//! Actions on objects and the dragged target, end to end against player-sim over real TCP:
//! robot r0 sees r1's fiducial marker (tagged `person` by the composition); clicking it while
//! r0 is active opens r0's popup of actions; "Follow" keeps r0 near r1 as r1 drives away, until
//! everything is stopped. And a target dragged over the ground in position mode is sent only
//! when it is let go, as one Player way-point the server drives to.

use std::path::PathBuf;
use std::time::Duration;

use framework::scene::NodeId;
use glam::Vec3;
use player_sim::sim::Command;
use pv3d::app::Viewer;
use tests::{load, repo_root, run_for, run_until, serve, sim_pose, viewer_for};

fn distance(a: (f64, f64, f64), b: (f64, f64, f64)) -> f64 {
    ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt()
}

/// A folder of its own for one test's world, cfg and composition.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pv3d-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Writes `follow.world` (r0 with a fiducial finder, r1 carrying marker 7, 2.5 m ahead of it)
/// with its cfg and a composition, in a scratch folder; returns (world, composition).
fn follow_world() -> (PathBuf, PathBuf) {
    let dir = scratch("follow");
    let robots_inc = repo_root().join("stage-worlds/robots.inc");
    std::fs::write(
        dir.join("follow.world"),
        format!(
            "include \"{}\"\ninterval_sim 100\n\
             rover( name \"r0\" pose [ 0 0 0 0 ] color \"red\" marker_finder( ) )\n\
             rover( name \"r1\" pose [ 2.5 0 0 0 ] color \"green\" fiducial_return 7 )\n",
            robots_inc.display()
        ),
    )
    .unwrap();
    std::fs::write(
        dir.join("follow.cfg"),
        "driver ( name \"stage\" provides [ \"6665:simulation:0\" ] plugin \"stageplugin\" worldfile \"follow.world\" )\n\
         driver ( name \"stage\" provides [ \"6665:position2d:0\" \"6665:fiducial:0\" ] model \"r0\" )\n\
         driver ( name \"stage\" provides [ \"6666:position2d:0\" ] model \"r1\" )\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("follow.pv3d.xml"),
        r#"<?xml version="1.0" encoding="UTF-8"?>
<pv3d>
  <handlers>
    <playerClient host="localhost" port="6665"/>
    <playerClient host="localhost" port="6666"/>
    <playerDeviceMask interface="position2d">
      <plugin library="libpv3d_position2d" id="robot">
        <playerDeviceMask interface="position2d" index="0"/>
        <followDistance>0.9</followDistance>
      </plugin>
    </playerDeviceMask>
    <playerDeviceMask interface="fiducial">
      <plugin library="libpv3d_fiducial" id="markers">
        <playerDeviceMask interface="fiducial" index="0"/>
        <parentNode interface="position2d" index="0"/>
        <tag id="7">person</tag>
      </plugin>
    </playerDeviceMask>
  </handlers>
</pv3d>
"#,
    )
    .unwrap();
    (dir.join("follow.world"), dir.join("follow.pv3d.xml"))
}

/// The robot body drawn nearest to `pose`.
fn robot_near(viewer: &Viewer, pose: (f64, f64, f64)) -> NodeId {
    let scene = viewer.scene();
    scene
        .iter()
        .filter(|(_, o)| o.has_tag("robot"))
        .map(|(id, _)| (id, Vec3::from(scene.world_transform(id).translation)))
        .min_by(|a, b| {
            let d = |p: Vec3| (p.x as f64 - pose.0).hypot(p.y as f64 - pose.1);
            d(a.1).total_cmp(&d(b.1))
        })
        .expect("robots drawn")
        .0
}

fn marker_tagged(viewer: &Viewer, tag: &str) -> Option<NodeId> {
    viewer
        .scene()
        .iter()
        .find(|(_, o)| o.has_tag(tag))
        .map(|(id, _)| id)
}

#[test]
fn clicking_a_person_marker_offers_actions_and_follow_keeps_near_it() {
    let (world, composition_file) = follow_world();
    let mut composition = load(&[composition_file.to_str().unwrap()]);
    let running = serve(world.to_str().unwrap(), &mut composition, 4.0);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);

    run_until(
        &mut viewer,
        "r0 to see the person",
        Duration::from_secs(10),
        |v| marker_tagged(v, "person").is_some() && v.scene().iter().count() > 3,
    );
    run_for(&mut viewer, Duration::from_millis(300));
    // Nothing active: clicking the marker opens nothing.
    let person = marker_tagged(&viewer, "person").unwrap();
    viewer.click(Some(person), None);
    assert_eq!(viewer.popup_actions(), None);

    // Select r0 by clicking it, then click the person.
    let r0 = robot_near(&viewer, sim_pose(&running, 0));
    viewer.click(Some(r0), None);
    assert!(viewer.active_title().is_some());
    let person = marker_tagged(&viewer, "person").unwrap();
    viewer.click(Some(person), None);
    assert_eq!(viewer.popup_actions(), Some(vec!["Go to", "Follow"]));
    let title = viewer.popup_title().unwrap();
    assert!(
        title.contains("person") && title.contains("id:7"),
        "{title}"
    );
    assert!(!viewer.choose_action("Dance"), "not an action on offer");
    // A click on the ground closes the popup and sends nobody anywhere.
    let before = sim_pose(&running, 0);
    viewer.click(None, Some(Vec3::new(-3.0, 0.0, 0.0)));
    assert_eq!(viewer.popup_actions(), None);
    run_for(&mut viewer, Duration::from_millis(300));
    assert!(distance(sim_pose(&running, 0), before) < 0.01);
    viewer.click(Some(marker_tagged(&viewer, "person").unwrap()), None);
    assert!(viewer.choose_action("Follow"));
    assert_eq!(viewer.popup_actions(), None, "the popup closes");

    // r0 closes in to 0.9 m of r1 (2.5 m away at the start) and holds there.
    run_until(
        &mut viewer,
        "r0 to close in",
        Duration::from_secs(15),
        |_| distance(sim_pose(&running, 0), sim_pose(&running, 1)) < 1.05,
    );
    // r1 walks off along +x; r0 follows, though its marker is re-created every scan.
    running.sim.lock().unwrap().robots[1].command = Command::Velocity {
        vx: 0.25,
        vy: 0.0,
        va: 0.0,
    };
    let start = sim_pose(&running, 0);
    run_until(
        &mut viewer,
        "r0 to follow r1",
        Duration::from_secs(15),
        |_| sim_pose(&running, 0).0 > start.0 + 1.5,
    );
    running.sim.lock().unwrap().robots[1].command = Command::Velocity {
        vx: 0.0,
        vy: 0.0,
        va: 0.0,
    };
    run_until(
        &mut viewer,
        "r0 to catch up",
        Duration::from_secs(15),
        |_| {
            let gap = distance(sim_pose(&running, 0), sim_pose(&running, 1));
            gap < 1.05
        },
    );
    let gap = distance(sim_pose(&running, 0), sim_pose(&running, 1));
    assert!(gap > 0.6, "kept its distance: {gap}");

    // Until stopped.
    viewer.stop_all();
    running.sim.lock().unwrap().robots[1].command = Command::Velocity {
        vx: 0.25,
        vy: 0.0,
        va: 0.0,
    };
    run_for(&mut viewer, Duration::from_millis(300));
    let stopped = sim_pose(&running, 0);
    run_for(&mut viewer, Duration::from_millis(800));
    assert!(
        distance(sim_pose(&running, 0), stopped) < 0.02,
        "r0 kept following after Stop"
    );
}

#[test]
fn a_dragged_target_in_position_mode_is_one_waypoint_sent_on_release() {
    let dir = scratch("drag");
    let composition_file = dir.join("position.pv3d.xml");
    std::fs::write(
        &composition_file,
        r#"<?xml version="1.0" encoding="UTF-8"?>
<pv3d>
  <handlers>
    <playerClient host="localhost" port="6665"/>
    <playerDeviceMask interface="position2d">
      <plugin library="libpv3d_position2d" id="robot">
        <playerDeviceMask interface="position2d" index="0"/>
        <mode>position</mode>
      </plugin>
    </playerDeviceMask>
  </handlers>
</pv3d>
"#,
    )
    .unwrap();
    let mut composition = load(&[composition_file.to_str().unwrap()]);
    let running = serve("stage-worlds/simple.world", &mut composition, 4.0);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    run_for(&mut viewer, Duration::from_millis(500));
    let start = sim_pose(&running, 0);
    viewer.cycle_active();

    // Dragging: shown, not sent.
    for step in 1..=5 {
        let p = Vec3::new(
            start.0 as f32 + 0.3 * step as f32,
            start.1 as f32 + 0.2,
            0.0,
        );
        viewer.drag_target(p);
        run_for(&mut viewer, Duration::from_millis(60));
    }
    assert!(
        distance(sim_pose(&running, 0), start) < 0.01,
        "the robot moved before the target was let go"
    );
    let target = (start.0 + 1.5, start.1 + 1.0, 0.0);
    viewer.release_target(Some(Vec3::new(target.0 as f32, target.1 as f32, 0.0)));
    run_for(&mut viewer, Duration::from_millis(100));
    assert!(
        matches!(
            running.sim.lock().unwrap().robots[0].command,
            Command::GoTo { .. }
        ),
        "position mode sends a way-point, the server drives"
    );
    run_until(
        &mut viewer,
        "the dropped target",
        Duration::from_secs(20),
        |_| distance(sim_pose(&running, 0), target) < 0.1,
    );
}

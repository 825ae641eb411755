//! A world that is aware, end to end over TCP — the classroom scenario of
//! `configs/aware-classroom.pv3d.xml`: player-sim's visitor walks their loop in people.world,
//! through the "keep out" zone; the robot's laser sees their legs; libpv3d_people puts a
//! `person` in the scene; the robot, told in words to follow the person, follows — and waits
//! at the edge of "keep out" when the visitor walks in, never entering it; the composition's
//! reaction fires (it says so, and loads a laser view bound to the robot's own laser).

use std::time::{Duration, Instant};

use framework::query::Query;
use tests::{load, run_until, serve, sim_pose, viewer_for};

const ENTERED: &str = "Someone walked into the keep-out area; the robot waits.";
/// The keep-out zone of aware-classroom.pv3d.xml: x from -0.6 to 0.6, y from 0.6 to 1.6.
const KEEP_OUT: (f64, f64, f64, f64) = (-0.6, 0.6, 0.6, 1.6);

fn in_keep_out((x, y, _): (f64, f64, f64)) -> bool {
    (KEEP_OUT.0..=KEEP_OUT.1).contains(&x) && (KEEP_OUT.2..=KEEP_OUT.3).contains(&y)
}

#[test]
fn a_robot_told_to_follow_a_person_stops_at_keep_out_and_the_reaction_fires() {
    let mut composition = load(&["configs/aware-classroom.pv3d.xml"]);
    let running = serve("stage-worlds/people.world", &mut composition, 2.0);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);

    // The visitor, on x = 0, is the person nearest the robot (at x = -3); the pupil wanders
    // near x = 3.
    run_until(
        &mut viewer,
        "the visitor found by the laser",
        Duration::from_secs(20),
        |v| {
            let scene = v.scene();
            scene.iter().any(|(id, o)| {
                o.has_tag("person") && scene.world_transform(id).translation.x.abs() < 1.0
            })
        },
    );
    let any = Query::parse(r#"<query to="world" name="is there any" tag="person"/>"#).unwrap();
    let count: usize = viewer
        .ask(&any)
        .unwrap()
        .body
        .attr("count")
        .unwrap()
        .parse()
        .unwrap();
    assert!(count >= 1);

    let reply = viewer.command("robot follow the person").unwrap();
    assert_eq!(reply, "robot: following the person");

    // Follow until the visitor has walked into "keep out" and the reaction fired, and a while
    // after: the robot never stands in the zone.
    let start = sim_pose(&running, 0);
    let (mut nearest_to_zone, mut moved) = (f64::INFINITY, 0.0_f64);
    let mut waited_at_edge = false;
    let deadline = Instant::now() + Duration::from_secs(60);
    let mut fired_at = None;
    while fired_at.is_none_or(|at: Instant| at.elapsed() < Duration::from_secs(4)) {
        assert!(
            Instant::now() < deadline,
            "no keep-out reaction: {:?}",
            viewer.reactions()
        );
        viewer.update(Instant::now());
        std::thread::sleep(Duration::from_millis(20));
        let pose = sim_pose(&running, 0);
        assert!(!in_keep_out(pose), "the robot entered keep out at {pose:?}");
        let dx = (KEEP_OUT.0 - pose.0).max(pose.0 - KEEP_OUT.1).max(0.0);
        let dy = (KEEP_OUT.2 - pose.1).max(pose.1 - KEEP_OUT.3).max(0.0);
        nearest_to_zone = nearest_to_zone.min(dx.hypot(dy));
        moved = moved.max((pose.0 - start.0).hypot(pose.1 - start.1));
        if fired_at.is_none() && viewer.reactions().said.iter().any(|s| s == ENTERED) {
            fired_at = Some(Instant::now());
        }
        let robot = Query::parse(r#"<query to="robot">where are you</query>"#).unwrap();
        let here = viewer.ask(&robot).unwrap();
        waited_at_edge |= here
            .body
            .child("waiting")
            .is_some_and(|w| w.attr("zone") == Some("keep out"));
    }
    assert!(moved > 1.5, "the robot followed: it moved {moved:.2} m");
    assert!(waited_at_edge, "the robot never had to wait at keep out");
    assert!(
        nearest_to_zone < 0.8,
        "it followed up to the zone's edge: {nearest_to_zone:.2} m"
    );
    assert!(
        viewer
            .reactions()
            .fired
            .iter()
            .any(|f| f.starts_with("enter person") && f.ends_with("keep out")),
        "{:?}",
        viewer.reactions().fired
    );
    // The reaction's <load>: a second laser view, bound to the robot's own laser (and only
    // one, though the visitor walks in again and again).
    let titles = viewer.titles();
    let laser_views = titles
        .iter()
        .filter(|t| t.starts_with("Laser") && t.contains("laser:0"))
        .count();
    assert_eq!(laser_views, 2, "{titles:?}");
}

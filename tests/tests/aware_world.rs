//! A world that is aware, end to end over TCP: player-sim's visitor walks their loop in
//! people.world; the robot's laser sees their legs; libpv3d_people puts a `person` in the
//! scene; the visitor walks into the "keep out" zone; and the composition's reaction fires —
//! it stops the robot (a query) and says so.

use std::time::Duration;

use framework::query::Query;
use tests::{load, run_until, serve, viewer_for};

const ENTERED: &str = "Someone walked into the keep-out area; the robot waits.";

#[test]
fn a_person_walking_into_the_keep_out_zone_is_seen_tagged_and_reacted_to() {
    let mut composition = load(&["configs/aware-classroom.pv3d.xml"]);
    let _running = serve("stage-worlds/people.world", &mut composition, 4.0);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);

    run_until(
        &mut viewer,
        "a person found by the laser",
        Duration::from_secs(20),
        |v| v.scene().iter().any(|(_, o)| o.has_tag("person")),
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

    run_until(
        &mut viewer,
        "the keep-out reaction",
        Duration::from_secs(40),
        |v| v.reactions().said.iter().any(|s| s == ENTERED),
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
    let robot = Query::parse(r#"<query to="libpv3d_position2d">where are you</query>"#).unwrap();
    let reply = viewer.ask(&robot).unwrap();
    assert_eq!(reply.body.attr("stalled"), Some("false"), "{reply:?}");
    assert!(reply.body.child("goal").is_none(), "stopped: no goal");
}

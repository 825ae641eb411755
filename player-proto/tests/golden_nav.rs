//! Golden tests on the navigation captures (`captures/nav/`): Player's own `mapfile`, `amcl`
//! and `wavefront` drivers talking to libplayerc. Every message decodes typed and re-encodes
//! to the recorded bytes; the values are the ones libplayerc printed in the `.client.txt` file
//! of the same session (printed to 4 or 3 decimals, hence the tolerances).

mod support;

use player_proto::body_kind::DataBody;
use player_proto::interfaces::localize::{Localize, LocalizeData, cov};
use player_proto::interfaces::map::{Map, MapData};
use player_proto::interfaces::planner::{Planner, PlannerData};
use player_proto::message::{Body, Message};
use player_proto::wire::MsgType;
use support::captures::captures_dir;
use support::sessions::load;

/// libplayerc printed poses to 4 decimals in the localize and map sessions.
const PRINTED_4: f64 = 5e-5;
/// ... and to 3 in the planner's state lines.
const PRINTED_3: f64 = 5e-4;

fn near(actual: f64, printed: f64, tolerance: f64) -> bool {
    (actual - printed).abs() <= tolerance
}

fn pose_near(actual: (f64, f64, f64), printed: (f64, f64, f64), tolerance: f64) -> bool {
    near(actual.0, printed.0, tolerance)
        && near(actual.1, printed.1, tolerance)
        && near(actual.2, printed.2, tolerance)
}

fn acks(messages: &[Message]) -> impl Iterator<Item = &Body> {
    messages
        .iter()
        .filter(|m| m.header.msg_type == MsgType::Ack)
        .map(|m| &m.body)
}

#[test]
fn every_navigation_session_decodes_typed_and_reencodes_identically() {
    let dir = captures_dir().join("nav");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".jsonl"))
        .collect();
    names.sort();
    for expected in [
        "localize_hypotheses_setpose.jsonl",
        "map_info_data.jsonl",
        "planner_goal_waypoints.jsonl",
    ] {
        assert!(
            names.iter().any(|n| n == expected),
            "{expected} in {names:?}"
        );
    }
    for name in names {
        let (s2c, c2s) = load(&format!("nav/{name}"));
        assert!(!s2c.is_empty() && !c2s.is_empty(), "{name}");
    }
}

#[test]
fn amcl_hypotheses_set_pose_and_particles_match_libplayerc() {
    let (s2c, c2s) = load("nav/localize_hypotheses_setpose.jsonl");
    let beliefs: Vec<(&Message, &LocalizeData)> = s2c
        .iter()
        .filter_map(|m| LocalizeData::KIND.of(m).map(|d| (m, d)))
        .collect();
    assert_eq!(beliefs.len(), 10);
    assert!(
        beliefs
            .iter()
            .all(|(_, d)| d.hypoths.len() == 1 && d.pending_count == 0)
    );

    let (first_msg, first) = beliefs[0];
    assert!(near(first_msg.header.timestamp, 1_795_447_358.568, 1e-3));
    let h = first.best().unwrap();
    assert!(pose_near(
        (h.mean.px, h.mean.py, h.mean.pa),
        (-6.6055, -6.5451, 0.7849),
        PRINTED_4
    ));
    // Packed xx, yy, aa, xy, ya, xa: amcl fills the xy term and leaves the yaw cross terms 0.
    assert!((h.cov[cov::XX] - 0.000437996).abs() < 1e-9);
    assert!((h.cov[cov::YY] - 0.000765656).abs() < 1e-9);
    assert!((h.cov[cov::AA] - 9.49564e-07).abs() < 1e-12);
    assert!((h.cov[cov::XY] - 0.000204822).abs() < 1e-9);
    assert_eq!((h.cov[cov::YA], h.cov[cov::XA]), (0.0, 0.0));
    assert!(
        near(h.alpha, 1.0, 1e-12),
        "one hypothesis holds all the weight"
    );
    let last = beliefs[9].1.best().unwrap();
    assert!(pose_near(
        (last.mean.px, last.mean.py, last.mean.pa),
        (-6.6087, -6.6104, 0.8342),
        PRINTED_4
    ));

    let set_pose = c2s
        .iter()
        .find_map(|m| Localize::REQ_SET_POSE.of(m))
        .expect("the client's SET_POSE");
    assert!(pose_near(
        (set_pose.mean.px, set_pose.mean.py, set_pose.mean.pa),
        (-6.5, -6.5, std::f64::consts::FRAC_PI_4),
        PRINTED_4
    ));
    assert_eq!(set_pose.cov, [0.05, 0.05, 0.05, 0.0, 0.0, 0.0]);

    let particles = acks(&s2c)
        .find_map(|b| Localize::REQ_GET_PARTICLES.body_of(b))
        .expect("the particles ACK");
    assert_eq!(particles.particles.len(), 101);
    assert!(pose_near(
        (particles.mean.px, particles.mean.py, particles.mean.pa),
        (-6.6087, -6.6104, 0.0),
        PRINTED_4
    ));
    assert!((particles.variance - 9.9476e-14).abs() < 1e-17);
    let p0 = particles.particles[0];
    assert!(pose_near(
        (p0.pose.px, p0.pose.py, p0.pose.pa),
        (-6.6087, -6.6104, 0.8332),
        PRINTED_4
    ));
    assert!((p0.alpha - 1.0 / 101.0).abs() < 1e-8);
    let weight_sum: f64 = particles.particles.iter().map(|p| p.alpha).sum();
    assert!((weight_sum - 1.0).abs() < 1e-9);
    // SET_POSE has a null reply: its ACK comes back without a body.
    let set_pose_ack = s2c
        .iter()
        .find(|m| {
            m.header.msg_type == MsgType::Ack && Localize::REQ_SET_POSE.kind().matches(&m.header)
        })
        .expect("the SET_POSE ACK");
    assert_eq!(set_pose_ack.body, Body::Empty);
}

#[test]
fn wavefront_state_goal_waypoints_and_enable_match_libplayerc() {
    let (s2c, c2s) = load("nav/planner_goal_waypoints.jsonl");
    let states: Vec<&PlannerData> = s2c.iter().filter_map(|m| PlannerData::KIND.of(m)).collect();
    assert_eq!(states.len(), 92);
    let first = states[0];
    assert!(!first.is_valid() && !first.is_done() && first.waypoints_count == 0);

    let planned = states
        .iter()
        .find(|s| s.is_valid())
        .expect("a state with a plan");
    assert!(pose_near(
        (planned.pos.px, planned.pos.py, planned.pos.pa),
        (-6.609, -6.594, 0.870),
        PRINTED_3
    ));
    assert!(pose_near(
        (
            planned.waypoint.px,
            planned.waypoint.py,
            planned.waypoint.pa
        ),
        (-2.0, -1.9, 1.571),
        PRINTED_3
    ));
    assert_eq!((planned.waypoint_idx, planned.waypoints_count), (2, 3));

    let last = states.last().unwrap();
    assert!(last.is_valid() && last.is_done());
    assert!(pose_near(
        (last.pos.px, last.pos.py, last.pos.pa),
        (-2.047, 0.031, 1.469),
        PRINTED_3
    ));
    assert!(pose_near(
        (last.goal.px, last.goal.py, last.goal.pa),
        (-2.0, 0.5, 1.571),
        PRINTED_3
    ));
    assert_eq!((last.waypoint_idx, last.waypoints_count), (0, 0));

    let goals: Vec<_> = c2s.iter().filter_map(|m| Planner::CMD_GOAL.of(m)).collect();
    assert_eq!(goals.len(), 1);
    assert_eq!(
        (goals[0].goal.px, goals[0].goal.py),
        (-2.0, 0.5),
        "sent as typed"
    );
    assert!(near(goals[0].goal.pa, std::f64::consts::FRAC_PI_2, 1e-9));

    let waypoints: Vec<_> = acks(&s2c)
        .filter_map(|b| Planner::REQ_GET_WAYPOINTS.body_of(b))
        .collect();
    assert_eq!(waypoints.len(), 3);
    assert!(waypoints[0].waypoints.is_empty() && waypoints[0].waypoints_distance == 0.0);
    for plan in &waypoints[1..] {
        assert!(near(plan.waypoints_distance, 8.9765, PRINTED_4));
        let points: Vec<_> = plan.waypoints.iter().map(|w| (w.px, w.py, w.pa)).collect();
        assert_eq!(points.len(), 3);
        for (got, printed) in
            points
                .iter()
                .zip([(-6.6, -6.6, 0.0), (-2.0, -1.9, 0.0), (-2.0, 0.5, 0.0)])
        {
            assert!(pose_near(*got, printed, PRINTED_4), "{got:?}");
        }
    }
    // The waypoint requests go out bodiless; the typed body is only in the ACK.
    let asked = c2s
        .iter()
        .filter(|m| Planner::REQ_GET_WAYPOINTS.kind().matches(&m.header))
        .count();
    assert_eq!(asked, 3);

    let enables: Vec<u8> = c2s
        .iter()
        .filter_map(|m| Planner::REQ_ENABLE.of(m).map(|e| e.state))
        .collect();
    assert_eq!(enables, [0, 1], "paused, then resumed");
}

#[test]
fn mapfile_info_and_compressed_tiles_match_libplayerc() {
    let (s2c, _) = load("nav/map_info_data.jsonl");
    let info = acks(&s2c)
        .find_map(|b| Map::REQ_GET_INFO.body_of(b))
        .expect("the info ACK");
    assert_eq!((info.width, info.height), (160, 160));
    assert!((info.scale - 0.1).abs() < 1e-6);
    assert_eq!((info.origin.px, info.origin.py), (-8.0, -8.0));

    let tiles: Vec<&MapData> = acks(&s2c)
        .filter_map(|b| Map::REQ_GET_DATA.body_of(b))
        .collect();
    assert_eq!(tiles.len(), 2, "the whole map, then a sub-tile");
    let whole = tiles[0];
    assert_eq!(
        (whole.col, whole.row, whole.width, whole.height),
        (0, 0, 160, 160)
    );
    assert_eq!(whole.data_range, 1);
    let cells = whole.cells().unwrap();
    let occupied = cells.iter().filter(|&&c| c == 1).count();
    let free = cells.iter().filter(|&&c| c == -1).count();
    assert_eq!((occupied, free), (1681, 23919));
    let mut crc = flate2::Crc::new();
    crc.update(&cells.iter().map(|&c| c as u8).collect::<Vec<u8>>());
    assert_eq!(crc.sum(), 0x4fec_400e);

    let sub = tiles[1];
    assert_eq!((sub.col, sub.row, sub.width, sub.height), (24, 96, 32, 16));
    assert_eq!(sub.data.len(), 35, "compressed bytes");
    assert_eq!(
        &sub.data[..8],
        &[0x78, 0x9c, 0xfb, 0xff, 0x7f, 0xa8, 0x00, 0x46]
    );
    let sub_cells = sub.cells().unwrap();
    // Tile row 6 (map row 102): columns 9 to 24 are wall.
    let row6: Vec<bool> = sub_cells[6 * 32..7 * 32].iter().map(|&c| c == 1).collect();
    assert!(
        row6.iter()
            .enumerate()
            .all(|(i, &wall)| wall == (9..=24).contains(&i))
    );
    for j in 0..16 {
        for i in 0..32 {
            let full = cells[(96 + j) * 160 + 24 + i];
            assert_eq!(
                sub_cells[j * 32 + i],
                full,
                "cell ({i}, {j}) of the sub-tile"
            );
        }
    }
    let vector_nack = s2c
        .iter()
        .find(|m| m.header.msg_type == MsgType::Nack)
        .expect("mapfile has no vector map");
    assert!(Map::REQ_GET_VECTOR.kind().matches(&vector_nack.header));
}

//! The navigation interfaces byte by byte: `localize` (code 25, 0x19) and `planner` (code 44,
//! 0x2c). Most messages are real ones from `captures/nav/` (amcl and wavefront talking to
//! libplayerc), laid out field by field as the protocol's tables give them.

mod support;

use bytes::Bytes;
use player_proto::interfaces::localize::{Localize, cov};
use player_proto::interfaces::planner::Planner;
use player_proto::message::{Body, Message};
use player_proto::wire::MsgType;
use player_proto::wire::xdr::XdrFault;
use support::annotated::{hex, message};

#[test]
fn amcl_hypotheses() {
    let m = message(
        "0100007f 00001a09 00000019 00000000 // 127.0.0.1:6665 localize:0
         00000001 00000001                   // DATA, HYPOTHS
         41dac1168fa45b4b 00000000 00000064  // time, seq, 100 body bytes
         00000000                            // pending_count
         0000000000000000                    // pending_time
         00000001 00000001                   // hypoths_count, then XDR's own length
         c01a6c04358097ca                    // mean.px  -6.6055
         c01a2e30db6489ca                    // mean.py  -6.5451
         3fe91dfdc7b630e7                    // mean.pa   0.7849
         3f3cb459850a0000                    // cov xx
         3f4916c9ccc40000                    // cov yy
         3eafdcb052c61d22                    // cov aa
         3f2ad8b2432c0000                    // cov xy
         0000000000000000                    // cov ya
         0000000000000000                    // cov xa
         3ff0000000000003                    // alpha (1 + 3 ulp)",
    );
    let Body::Localize(Localize::Hypotheses(data)) = &m.body else {
        panic!("{:?}", m.body)
    };
    assert_eq!((data.pending_count, data.pending_time), (0, 0.0));
    let h = data.hypoths[0];
    assert!((h.mean.px + 6.6055).abs() < 5e-5 && (h.mean.pa - 0.7849).abs() < 5e-5);
    assert!((h.cov[cov::XY] - 0.000204822).abs() < 1e-9);
    assert!((h.alpha - 1.0).abs() < 1e-15);
}

#[test]
fn set_pose_request_and_its_null_reply() {
    let m = message(
        "00000000 00001a09 00000019 00000000 // client side: host 0, robot 6665
         00000003 00000001                   // REQ, SET_POSE
         41dac116901c7e80 00000000 00000048  // time, seq, 72 body bytes
         c01a000000000000                    // mean.px -6.5
         c01a000000000000                    // mean.py -6.5
         3fe921fb54442d18                    // mean.pa  pi/4
         3fa999999999999a                    // cov xx 0.05 (fixed vector: no count)
         3fa999999999999a                    // cov yy 0.05
         3fa999999999999a                    // cov aa 0.05
         0000000000000000 0000000000000000 0000000000000000 // xy, ya, xa",
    );
    let request = Localize::REQ_SET_POSE.of(&m).expect("a SET_POSE");
    assert_eq!(
        (request.mean.px, request.mean.pa),
        (-6.5, std::f64::consts::FRAC_PI_4)
    );
    assert_eq!(request.cov, [0.05, 0.05, 0.05, 0.0, 0.0, 0.0]);

    let ack = message(
        "0100007f 00001a09 00000019 00000000
         00000004 00000001                   // ACK, SET_POSE
         41dac116901c9707 00000000 00000000  // no body",
    );
    assert_eq!(ack.body, Body::Empty);
}

#[test]
fn a_three_double_covariance_of_player_3_0_is_refused_not_misread() {
    // Player 3.0 sent `cov[3]`: 48 bytes where 3.1 expects 72.
    let body = Bytes::from(hex(
        "c01a000000000000 c01a000000000000 3fe921fb54442d18 // mean
         3fa999999999999a 3fa999999999999a 3fa999999999999a // cov[3]",
    ));
    let mut header = Message::typed(
        "localize:0".parse().unwrap(),
        MsgType::Req,
        Localize::REQ_SET_POSE.to_body(Default::default()),
    )
    .header;
    header.size = body.len() as u32;
    let err = Message::decode(header, body).unwrap_err();
    assert_eq!(err.fault, XdrFault::Truncated);
    assert_eq!(err.field.as_deref(), Some("LocalizeSetPose.cov"));
}

#[test]
fn particle_set() {
    let m = message(
        "0100007f 00001a09 00000019 00000000
         00000004 00000002                   // ACK, GET_PARTICLES
         0000000000000000 00000000 00000068  // time 0, seq, 104 body bytes
         3ff0000000000000 4000000000000000 0000000000000000 // mean (1, 2, 0)
         3fd0000000000000                    // variance 0.25
         00000002 00000002                   // particles_count, length
         3ff0000000000000 4000000000000000 3fe0000000000000 // pose (1, 2, 0.5)
         3fe8000000000000                    // alpha 0.75
         3ff8000000000000 4000000000000000 bfe0000000000000 // pose (1.5, 2, -0.5)
         3fd0000000000000                    // alpha 0.25",
    );
    let set = Localize::REQ_GET_PARTICLES.of(&m).expect("particles");
    assert_eq!((set.mean.py, set.variance), (2.0, 0.25));
    let poses: Vec<_> = set
        .particles
        .iter()
        .map(|p| (p.pose.px, p.pose.pa, p.alpha))
        .collect();
    assert_eq!(poses, [(1.0, 0.5, 0.75), (1.5, -0.5, 0.25)]);
}

#[test]
fn wavefront_state_with_a_plan() {
    let m = message(
        "0100007f 00001a09 0000002c 00000000 // planner:0
         00000001 00000001                   // DATA, STATE
         41dac116935a4695 00000000 00000058  // time, seq, 88 body bytes
         00000001                            // valid (uint8 widened)
         00000000                            // done
         c01a6f55fe93331d c01a6005901bb813 3febd7c2e8575b4e // pos
         c000000000000000 3fe0000000000000 3ff921fb54442d18 // goal (-2, 0.5, pi/2)
         bfffffffe8000000 bffe66664e000000 3ff921fb54442d18 // waypoint (-2, -1.9) as f32
         00000002                            // waypoint_idx
         00000003                            // waypoints_count: a number, no array follows",
    );
    let Body::Planner(Planner::State(state)) = m.body else {
        panic!("{:?}", m.body)
    };
    assert!(state.is_valid() && !state.is_done());
    assert_eq!((state.goal.px, state.goal.py), (-2.0, 0.5));
    assert_eq!((state.waypoint_idx, state.waypoints_count), (2, 3));
    assert!((state.waypoint.py + 1.9).abs() < 1e-6);
}

#[test]
fn goal_command() {
    let m = message(
        "00000000 00001a09 0000002c 00000000
         00000002 00000001                   // CMD, GOAL
         41dac11693478c58 00000000 00000018  // time, seq, 24 body bytes
         c000000000000000 3fe0000000000000 3ff921fb54442d18 // goal (-2, 0.5, pi/2)",
    );
    let goal = Planner::CMD_GOAL.of(&m).expect("a goal");
    assert_eq!(
        (goal.goal.px, goal.goal.py, goal.goal.pa),
        (-2.0, 0.5, std::f64::consts::FRAC_PI_2)
    );
}

#[test]
fn waypoints_reply() {
    let m = message(
        "0100007f 00001a09 0000002c 00000000
         00000004 00000001                   // ACK, GET_WAYPOINTS
         41dac1169360b181 00000000 00000058  // time, seq, 88 body bytes
         4021f3f450b6e44f                    // waypoints_distance 8.9765 m
         00000003 00000003                   // waypoints_count, length
         c01a666665000000 c01a666665000000 0000000000000000 // (-6.6, -6.6, 0)
         bfffffffe8000000 bffe66664e000000 0000000000000000 // (-2, -1.9, 0)
         bfffffffe8000000 3fe0000044000000 0000000000000000 // (-2, 0.5, 0)",
    );
    let plan = Planner::REQ_GET_WAYPOINTS.of(&m).expect("waypoints");
    assert!((plan.waypoints_distance - 8.9765).abs() < 5e-5);
    let ys: Vec<f64> = plan.waypoints.iter().map(|w| w.py).collect();
    assert!(
        ys.iter()
            .zip([-6.6, -1.9, 0.5])
            .all(|(y, want)| (y - want).abs() < 1e-6),
        "{ys:?}"
    );
}

#[test]
fn enable_request() {
    let m = message(
        "00000000 00001a09 0000002c 00000000
         00000003 00000002                   // REQ, ENABLE
         41dac11695630742 00000000 00000004  // time, seq, 4 body bytes
         00000000                            // state: 0 = stop the robot",
    );
    let enable = Planner::REQ_ENABLE.of(&m).expect("an enable request");
    assert!(!enable.is_on());
}

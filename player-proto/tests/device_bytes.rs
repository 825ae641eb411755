//! The rest of a real robot's devices byte by byte: `ptz` (code 8), `ir` (22, 0x16),
//! `speech_recognition` (50, 0x32) and `pointcloud3d` (61, 0x3d), written out field by field
//! from the protocol's tables.

mod support;

use bytes::Bytes;
use player_proto::interfaces::ir::Ir;
use player_proto::interfaces::pointcloud3d::Pointcloud3d;
use player_proto::interfaces::ptz::{POSITION_CONTROL, Ptz};
use player_proto::interfaces::speech_recognition::SpeechRecognition;
use player_proto::message::{Body, Message};
use player_proto::wire::xdr::XdrFault;
use player_proto::wire::{DevAddr, MsgType};
use support::annotated::{hex, message};

#[test]
fn ptz_state_and_command() {
    let state = message(
        "0100007f 00001a09 00000008 00000000 // 127.0.0.1:6665 ptz:0
         00000001 00000001                   // DATA, STATE
         41d954fc40200000 00000000 00000018  // time, seq, 24 body bytes
         3f000000                            // pan 0.5 rad
         be800000                            // tilt -0.25 rad
         3f800000                            // zoom (field of view) 1 rad
         00000000                            // panspeed 0
         3e000000                            // tiltspeed 0.125 rad/s
         00000003                            // status bits",
    );
    let Body::Ptz(Ptz::State(s)) = state.body else {
        panic!("{:?}", state.body)
    };
    assert_eq!(
        (s.pan, s.tilt, s.zoom, s.tiltspeed, s.status),
        (0.5, -0.25, 1.0, 0.125, 3)
    );

    let command = message(
        "00000000 00001a09 00000008 00000000
         00000002 00000001                   // CMD, STATE
         41d954fc40200000 00000000 00000014  // 20 body bytes: no status word
         3f800000 00000000 3f000000          // pan 1, tilt 0, zoom 0.5
         3e800000 3e800000                   // panspeed, tiltspeed 0.25",
    );
    let c = Ptz::CMD_STATE.of(&command).expect("a ptz command");
    assert_eq!((c.pan, c.zoom, c.panspeed), (1.0, 0.5, 0.25));
}

#[test]
fn ptz_requests() {
    let generic = message(
        "00000000 00001a09 00000008 00000000
         00000003 00000001                   // REQ, GENERIC
         41d954fc40200000 00000000 00000010
         00000002 00000002                   // config_count, length
         0000002a deadbeef                   // unit-specific words",
    );
    let words = Ptz::REQ_GENERIC.of(&generic).expect("a generic request");
    assert_eq!(words.config, [42, 0xdead_beef]);

    let mode = message(
        "00000000 00001a09 00000008 00000000
         00000003 00000002                   // REQ, CONTROL_MODE
         41d954fc40200000 00000000 00000004
         00000001                            // position control",
    );
    let mode = Ptz::REQ_CONTROL_MODE.of(&mode).expect("a control mode");
    assert_eq!(mode.mode, POSITION_CONTROL);

    let geometry = message(
        "0100007f 00001a09 00000008 00000000
         00000004 00000004                   // ACK, GEOM (subtype 3 is unused)
         41d954fc40200000 00000000 00000048  // 72 body bytes
         3fb999999999999a 0000000000000000 3fd3333333333333 // pos x 0.1, y 0, z 0.3
         0000000000000000 0000000000000000 0000000000000000 // roll, pitch, yaw
         3fd0000000000000 3fd0000000000000 3fc0000000000000 // size w 0.25, l 0.25, h 0.125",
    );
    let g = Ptz::REQ_GEOM.of(&geometry).expect("a geometry reply");
    assert_eq!((g.pos.px, g.pos.pz, g.size.sh), (0.1, 0.3, 0.125));

    let status = message(
        "0100007f 00001a09 00000008 00000000
         00000004 00000005                   // ACK, STATUS
         41d954fc40200000 00000000 00000004
         00000007                            // status word",
    );
    assert_eq!(Ptz::REQ_STATUS.of(&status).map(|s| s.status), Some(7));
}

#[test]
fn ir_ranges_poses_and_power() {
    let ranges = message(
        "0100007f 00001a09 00000016 00000000 // ir:0
         00000001 00000001                   // DATA, RANGES
         41d954fc40200000 00000000 00000020  // 32 body bytes
         00000002 00000002                   // voltages_count, length
         40200000 3fa00000                   // 2.5 V, 1.25 V
         00000002 00000002                   // ranges_count, length
         3f000000 3f400000                   // 0.5 m, 0.75 m",
    );
    let Body::Ir(Ir::Ranges(r)) = ranges.body else {
        panic!("{:?}", ranges.body)
    };
    assert_eq!((r.voltages, r.ranges), (vec![2.5, 1.25], vec![0.5, 0.75]));

    let poses = message(
        "0100007f 00001a09 00000016 00000000
         00000004 00000001                   // ACK, POSE
         41d954fc40200000 00000000 00000038  // 56 body bytes
         00000001 00000001                   // poses_count, length
         3fc0000000000000 bfb0000000000000 0000000000000000 // x 0.125, y -0.0625, z 0
         0000000000000000 0000000000000000 3ff921fb54442d18 // roll, pitch, yaw pi/2",
    );
    let p = Ir::REQ_POSE.of(&poses).expect("a pose reply");
    assert_eq!(p.poses.len(), 1);
    assert_eq!(
        (p.poses[0].px, p.poses[0].py, p.poses[0].pyaw),
        (0.125, -0.0625, std::f64::consts::FRAC_PI_2)
    );

    let power = message(
        "00000000 00001a09 00000016 00000000
         00000003 00000002                   // REQ, POWER
         41d954fc40200000 00000000 00000004
         00000001                            // on (uint8 widened)",
    );
    assert!(Ir::REQ_POWER.of(&power).expect("a power request").is_on());
}

#[test]
fn recognised_speech_is_padded_text() {
    let m = message(
        "0100007f 00001a09 00000032 00000000 // speech_recognition:0
         00000001 00000001                   // DATA, STRING
         41d954fc40200000 00000000 00000010  // 16 body bytes
         00000006 00000006                   // text_count, length
         68656c6c 6f00 0000                  // 'hello' NUL, then 2 bytes of padding",
    );
    let Body::SpeechRecognition(SpeechRecognition::Text(t)) = m.body else {
        panic!("{:?}", m.body)
    };
    assert_eq!(t.text.as_str(), "hello");
    assert_eq!(t.text.wire_bytes(), b"hello\0");
}

#[test]
fn a_point_cloud_carries_a_widened_colour_per_point() {
    let m = message(
        "0100007f 00001a09 0000003d 00000000 // pointcloud3d:0
         00000001 00000001                   // DATA, STATE
         41d954fc40200000 00000000 00000058  // 88 body bytes
         00000002 00000002                   // points_count, length
         3ff0000000000000 4000000000000000 3fe0000000000000 // (1, 2, 0.5)
         00000000 000000ff 00000080 00000000 // alpha, red, green, blue
         bff0000000000000 0000000000000000 3fd0000000000000 // (-1, 0, 0.25)
         00000000 00000000 00000000 000000ff // blue",
    );
    let Body::Pointcloud3d(Pointcloud3d::State(cloud)) = m.body else {
        panic!("{:?}", m.body)
    };
    let first = cloud.points[0];
    assert_eq!(
        (first.point.px, first.point.py, first.point.pz),
        (1.0, 2.0, 0.5)
    );
    assert_eq!((first.color.red, first.color.green), (255, 128));
    assert_eq!(cloud.points[1].color.blue, 255);
}

#[test]
fn a_cloud_claiming_more_points_than_its_body_holds_is_refused() {
    // A million points announced, one word of body left: refused before allocating.
    let body = Bytes::from(hex("000f4240 000f4240 00000000"));
    let addr: DevAddr = "pointcloud3d:0".parse().unwrap();
    let mut header = Message::typed(
        addr,
        MsgType::Data,
        Pointcloud3d::DATA_STATE.to_body(Default::default()),
    )
    .header;
    header.size = body.len() as u32;
    let err = Message::decode(header, body).unwrap_err();
    assert_eq!(
        err.fault,
        XdrFault::LengthBeyondBody {
            length: 1_000_000,
            remaining: 4
        }
    );
    assert_eq!(err.field.as_deref(), Some("PointCloud3dData.points"));
}

//! A mobile base's own devices byte by byte: `power` (code 2), `gripper` (3), `blobfinder`
//! (7), `bumper` (14, 0x0e), and the `map` (42, 0x2a) structures the navigation captures lack
//! (the info as DATA, the vector map), written out field by field from the protocol's tables.

mod support;

use player_proto::body_kind::DataBody;
use player_proto::interfaces::blobfinder::Blobfinder;
use player_proto::interfaces::bumper::Bumper;
use player_proto::interfaces::gripper::{Gripper, STATE_CLOSED};
use player_proto::interfaces::map::{Map, MapInfo};
use player_proto::interfaces::power::{MASK_PERCENT, MASK_VOLTS, MASK_WATTS, Power};
use player_proto::message::Body;
use support::annotated::message;

#[test]
fn battery_state_and_charging_policy() {
    let state = message(
        "0100007f 00001a09 00000002 00000000 // 127.0.0.1:6665 power:0
         00000001 00000001                   // DATA, STATE
         41d954fc40200000 00000000 00000018  // time, seq, 24 body bytes
         0000000b                            // valid: volts | watts | percent
         41480000                            // volts 12.5
         42a00000                            // percent 80
         00000000                            // joules (not valid)
         c1a00000                            // watts -20: consuming
         ffffffff                            // charging -1: giving charge",
    );
    let Body::Power(Power::State(p)) = state.body else {
        panic!("{:?}", state.body)
    };
    assert_eq!(p.valid, MASK_VOLTS | MASK_WATTS | MASK_PERCENT);
    assert_eq!(
        (p.volts, p.percent, p.watts, p.charging),
        (12.5, 80.0, -20.0, -1)
    );

    let policy = message(
        "00000000 00001a09 00000002 00000000
         00000003 00000001                   // REQ, SET_CHARGING_POLICY
         41d954fc40200000 00000000 00000008
         00000001                            // enable_input (uint8 widened)
         00000000                            // enable_output",
    );
    let policy = Power::REQ_SET_CHARGING_POLICY
        .of(&policy)
        .expect("a policy");
    assert_eq!((policy.enable_input, policy.enable_output), (1, 0));
}

#[test]
fn gripper_state_and_geometry() {
    let state = message(
        "0100007f 00001a09 00000003 00000000 // gripper:0
         00000001 00000001                   // DATA, STATE
         41d954fc40200000 00000000 0000000c
         00000002                            // state: closed
         00000005                            // beams 0b101
         00000001                            // stored",
    );
    let Body::Gripper(Gripper::State(g)) = state.body else {
        panic!("{:?}", state.body)
    };
    assert_eq!((g.state, g.beams, g.stored), (STATE_CLOSED, 0b101, 1));

    let geometry = message(
        "0100007f 00001a09 00000003 00000000
         00000004 00000001                   // ACK, GET_GEOM
         41d954fc40200000 00000000 00000068  // 104 body bytes
         3fd0000000000000 0000000000000000 0000000000000000 // pose x 0.25
         0000000000000000 0000000000000000 0000000000000000 // roll, pitch, yaw
         3fd0000000000000 3fe0000000000000 3fc0000000000000 // outer 0.25 × 0.5 × 0.125
         3fc0000000000000 3fd0000000000000 3fb0000000000000 // inner 0.125 × 0.25 × 0.0625
         00000002                            // num_beams
         00000001                            // capacity",
    );
    let g = Gripper::REQ_GET_GEOM.of(&geometry).expect("a geometry");
    assert_eq!(
        (g.pose.px, g.outer_size.sl, g.inner_size.sh),
        (0.25, 0.5, 0.0625)
    );
    assert_eq!((g.num_beams, g.capacity), (2, 1));
}

#[test]
fn blobs_and_colour_and_imager_settings() {
    let blobs = message(
        "0100007f 00001a09 00000007 00000000 // blobfinder:0
         00000001 00000001                   // DATA, BLOBS
         41d954fc40200000 00000000 00000038  // 56 body bytes
         00000140 000000f0                   // image 320 × 240
         00000001 00000001                   // blobs_count, length
         00000001 00ff0000 00000064          // id 1, colour red, area 100
         000000a0 00000078                   // centroid (160, 120)
         0000009b 000000a5 00000073 0000007d // left, right, top, bottom
         40200000                            // range 2.5 m",
    );
    let Body::Blobfinder(Blobfinder::Blobs(b)) = blobs.body else {
        panic!("{:?}", blobs.body)
    };
    assert_eq!((b.width, b.height, b.blobs.len()), (320, 240, 1));
    let blob = b.blobs[0];
    assert_eq!(
        (blob.color, blob.x, blob.bottom, blob.range),
        (0xff0000, 160, 125, 2.5)
    );

    let colour = message(
        "00000000 00001a09 00000007 00000000
         00000003 00000001                   // REQ, SET_COLOR
         41d954fc40200000 00000000 0000001c
         00000000                            // channel
         000000c8 000000ff                   // red 200..255
         00000000 00000032                   // green 0..50
         00000000 00000032                   // blue 0..50",
    );
    let c = Blobfinder::REQ_SET_COLOR.of(&colour).expect("a colour");
    assert_eq!((c.rmin, c.rmax, c.gmax, c.bmax), (200, 255, 50, 50));

    let imager = message(
        "00000000 00001a09 00000007 00000000
         00000003 00000002                   // REQ, SET_IMAGER_PARAMS
         41d954fc40200000 00000000 00000010
         ffffffff 0000000a                   // brightness unchanged, contrast 10
         ffffffff 00000000                   // colormode unchanged, autogain off",
    );
    let i = Blobfinder::REQ_SET_IMAGER_PARAMS
        .of(&imager)
        .expect("imager settings");
    assert_eq!((i.brightness, i.contrast, i.colormode), (-1, 10, -1));
}

#[test]
fn bumper_state_and_geometry() {
    let state = message(
        "0100007f 00001a09 0000000e 00000000 // bumper:0
         00000001 00000001                   // DATA, STATE
         41d954fc40200000 00000000 00000010
         00000005 00000005                   // bumpers_count, length
         00010000 01 000000                  // one byte each: 2nd and 5th pressed, padding",
    );
    let Body::Bumper(Bumper::State(s)) = state.body else {
        panic!("{:?}", state.body)
    };
    assert_eq!(&s.bumpers[..], &[0, 1, 0, 0, 1]);

    let geometry = message(
        "0100007f 00001a09 0000000e 00000000
         00000004 00000001                   // ACK, GET_GEOM
         41d954fc40200000 00000000 00000040  // 64 body bytes
         00000001 00000001                   // bumper_def_count, length
         3fc999999999999a 0000000000000000 0000000000000000 // pose x 0.2
         0000000000000000 0000000000000000 0000000000000000 // roll, pitch, yaw
         3e99999a                            // length 0.3 m
         00000000                            // radius 0: straight",
    );
    let g = Bumper::REQ_GET_GEOM.of(&geometry).expect("a geometry");
    assert_eq!(g.bumper_def.len(), 1);
    assert_eq!(
        (g.bumper_def[0].pose.px, g.bumper_def[0].length),
        (0.2, 0.3)
    );
}

#[test]
fn map_info_as_data_and_the_vector_map() {
    let info = message(
        "0100007f 00001a09 0000002a 00000000 // map:0
         00000001 00000001                   // DATA, INFO
         41d954fc40200000 00000000 00000024  // 36 body bytes
         3dcccccd                            // scale 0.1 m per cell
         000000a0 000000a0                   // 160 × 160 cells
         c020000000000000 c020000000000000 0000000000000000 // origin (-8, -8, 0)",
    );
    let i: &MapInfo = MapInfo::KIND.of(&info).expect("info as data");
    assert_eq!((i.width, i.height, i.origin.px), (160, 160, -8.0));

    let vector = message(
        "0100007f 00001a09 0000002a 00000000
         00000004 00000003                   // ACK, GET_VECTOR
         41d954fc40200000 00000000 00000038  // 56 body bytes
         bf800000 3f800000                   // minx -1, maxx 1
         bf000000 3f000000                   // miny -0.5, maxy 0.5
         00000001 00000001                   // segments_count, length
         bff0000000000000 bfe0000000000000   // from (-1, -0.5)
         3ff0000000000000 3fe0000000000000   // to (1, 0.5)",
    );
    let v = Map::REQ_GET_VECTOR.of(&vector).expect("a vector map");
    assert_eq!((v.minx, v.maxy), (-1.0, 0.5));
    let s = v.segments[0];
    assert_eq!((s.x0, s.y0, s.x1, s.y1), (-1.0, -0.5, 1.0, 0.5));
}

//! The hex dumps of the protocol notes (produced by Player's own packers): each decodes to the
//! values the notes give and re-encodes to the same bytes.

use bytes::Bytes;
use player_proto::interfaces::camera::{Camera, FORMAT_MONO8};
use player_proto::interfaces::common::U32Value;
use player_proto::interfaces::laser::Laser;
use player_proto::interfaces::player::{
    Player, REQ_DATAMODE, REQ_DEV, REQ_DEVLIST, REQ_DRIVERINFO,
};
use player_proto::interfaces::position2d::Position2d;
use player_proto::interfaces::ranger::Ranger;
use player_proto::interfaces::universal::Universal;
use player_proto::message::{Body, Message};
use player_proto::wire::{FrameDecoder, Interface, MsgType};

fn hex(text: &str) -> Vec<u8> {
    let digits: String = text.split_whitespace().collect();
    (0..digits.len())
        .step_by(2)
        .map(|i| u8::from_str_radix(&digits[i..i + 2], 16).unwrap())
        .collect()
}

/// Frames one whole message, decodes it, and checks it re-encodes identically.
fn message(text: &str) -> Message {
    let bytes = hex(text);
    let mut frames = FrameDecoder::default();
    frames.extend(&bytes);
    let frame = frames.next_frame().unwrap().expect("a whole message");
    assert_eq!(frames.buffered(), 0, "exactly one message");
    let m = Message::decode(frame.header, frame.body).unwrap();
    assert_eq!(&m.to_bytes()[..], &bytes[..], "re-encoding");
    m
}

#[test]
fn laser_scan_of_section_2_4() {
    let m = message(
        "01 00 00 7f 00 00 1a 09 00 00 00 06 00 00 00 00 00 00 00 01 00 00 00 01
         41 d9 54 fc 40 20 00 00 00 00 00 00 00 00 00 34
         bf c9 0f db 3f c9 0f db 3f c9 0f db 41 00 00 00 00 00 00 03 00 00 00 03
         3f 80 00 00 40 20 00 00 40 80 00 00 00 00 00 02 00 00 00 02 01 ff 00 00 00 00 00 2a",
    );
    assert_eq!(
        (m.header.addr.robot, m.header.timestamp),
        (6665, 1_700_000_000.5)
    );
    let Body::Laser(Laser::Scan(scan)) = m.body else {
        panic!()
    };
    assert_eq!(scan.ranges, [1.0, 2.5, 4.0]);
    assert_eq!(&scan.intensity[..], &[1, 255]);
    assert_eq!((scan.id, scan.max_range), (42, 8.0));
    assert!((scan.min_angle + std::f32::consts::FRAC_PI_2).abs() < 1e-6);
}

#[test]
fn datamode_request_of_section_2_5() {
    let m = message(
        "00 00 00 00  00 00 00 00  00 00 00 01  00 00 00 00
         00 00 00 03  00 00 00 05
         41 d9 54 fc 40 20 00 00
         00 00 00 00  00 00 00 04
         00 00 00 02",
    );
    assert_eq!(
        (m.header.msg_type, m.header.subtype),
        (MsgType::Req, REQ_DATAMODE)
    );
    assert!(matches!(m.body, Body::Player(Player::DataMode(d)) if d.mode == 2));
}

#[test]
fn subscription_request_and_ack_of_section_4_3() {
    let req = message(
        "00 00 00 00 00 00 00 00 00 00 00 01 00 00 00 00 00 00 00 03 00 00 00 03
         41 d9 54 fc 40 20 00 00 00 00 00 00 00 00 00 1c
         00 00 00 00 00 00 00 00 00 00 00 06 00 00 00 00 00 00 00 01 00 00 00 00 00 00 00 00",
    );
    assert_eq!(req.header.subtype, REQ_DEV);
    let Body::Player(Player::Device(d)) = req.body else {
        panic!()
    };
    assert_eq!(
        (d.addr.interf, d.access, d.driver_name.wire_bytes().len()),
        (Interface::LASER, 1, 0)
    );

    let ack = message(
        "01 00 00 7f 00 00 1a 09 00 00 00 01 00 00 00 00 00 00 00 04 00 00 00 03
         41 d9 54 fc 40 20 00 00 00 00 00 00 00 00 00 28
         01 00 00 7f 00 00 1a 09 00 00 00 06 00 00 00 00 00 00 00 01 00 00 00 0b
         00 00 00 0b 73 69 63 6b 6c 6d 73 32 30 30 00 00",
    );
    let Body::Player(Player::Device(d)) = ack.body else {
        panic!()
    };
    assert_eq!(
        (d.access, d.driver_name.as_str().as_ref()),
        (1, "sicklms200")
    );
    assert_eq!(d.driver_name.wire_bytes(), b"sicklms200\0");
}

#[test]
fn velocity_command_of_section_5_3() {
    let m = message(
        "00 00 00 00 00 00 1a 09 00 00 00 04 00 00 00 00 00 00 00 02 00 00 00 01
         41 d9 54 fc 40 20 00 00 00 00 00 00 00 00 00 1c
         3f e0 00 00 00 00 00 00 00 00 00 00 00 00 00 00 3f d0 00 00 00 00 00 00 00 00 00 01",
    );
    let Body::Position2d(Position2d::Velocity(v)) = m.body else {
        panic!()
    };
    assert_eq!((v.vel.px, v.vel.py, v.vel.pa, v.state), (0.5, 0.0, 0.25, 1));
}

fn body_of(interf: Interface, msg_type: MsgType, subtype: u8, body: &str) -> Message {
    let bytes = Bytes::from(hex(body));
    let mut header = Message::new(
        player_proto::DevAddr::local(interf, 0),
        msg_type,
        subtype,
        Body::Empty,
    )
    .header;
    header.size = bytes.len() as u32;
    let m = Message::decode(header, bytes.clone()).unwrap();
    assert_eq!(m.to_bytes().slice(40..), bytes);
    m
}

#[test]
fn camera_and_ranger_bodies_of_sections_5_5_and_5_6() {
    let cam = body_of(
        Interface::CAMERA,
        MsgType::Data,
        1,
        "00000002 00000001 00000008 00000001 00000001 00000000 00000002 00000002 11220000",
    );
    let Body::Camera(Camera::State(frame)) = cam.body else {
        panic!()
    };
    assert_eq!(
        (frame.width, frame.height, frame.format, &frame.image[..]),
        (2, 1, FORMAT_MONO8, &[0x11, 0x22][..])
    );
    assert_eq!(
        frame.to_rgba().unwrap().get_pixel(1, 0).0,
        [0x22, 0x22, 0x22, 255]
    );

    let ranger = body_of(
        Interface::RANGER,
        MsgType::Data,
        1,
        "00000002 00000002 3ff0000000000000 4000000000000000",
    );
    assert!(matches!(ranger.body, Body::Ranger(Ranger::Ranges(r)) if r.ranges == [1.0, 2.0]));
}

#[test]
fn appendix_b_dumps() {
    let info = message(
        "00 00 00 00 00 00 00 00 00 00 00 01 00 00 00 00 00 00 00 03 00 00 00 02
         00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 18
         00 00 00 00 00 00 1a 09 00 00 00 06 00 00 00 00 00 00 00 00 00 00 00 00",
    );
    assert_eq!(info.header.subtype, REQ_DRIVERINFO);
    let list = message(
        "01 00 00 7f 00 00 1a 09 00 00 00 01 00 00 00 00 00 00 00 04 00 00 00 01
         41 d9 54 fc 40 20 00 00 00 00 00 00 00 00 00 28
         00 00 00 02 00 00 00 02
         01 00 00 7f 00 00 1a 09 00 00 00 04 00 00 00 00
         01 00 00 7f 00 00 1a 09 00 00 00 06 00 00 00 00",
    );
    assert_eq!(list.header.subtype, REQ_DEVLIST);
    let Body::Player(Player::DevList(d)) = list.body else {
        panic!()
    };
    assert_eq!(
        d.devices.iter().map(|a| a.interf).collect::<Vec<_>>(),
        [Interface::POSITION2D, Interface::LASER]
    );
    let overflow = message(
        "00 00 00 00 00 00 00 00 00 00 00 01 00 00 00 00 00 00 00 05 00 00 00 02
         00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 04 00 00 00 07",
    );
    assert_eq!(
        overflow.body,
        Body::Player(Player::SynchOverflow(U32Value { value: 7 }))
    );
    let prop = body_of(
        Interface::LASER,
        MsgType::Req,
        248,
        "00 00 00 04 00 00 00 04 61 62 63 00 00 00 00 01",
    );
    assert!(
        matches!(prop.body, Body::Universal(Universal::GetBoolProp(p)) if p.key.as_str() == "abc" && p.value == 1)
    );
}

//! Player's bounded arrays (§10 of the protocol document), refused before decoding when their
//! length lies; headers whose narrow fields overflow; trailing body bytes kept verbatim.

use bytes::{BufMut, Bytes, BytesMut};
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::interfaces::player::Player;
use player_proto::message::{Body, Message};
use player_proto::wire::xdr::XdrFault;
use player_proto::wire::{DevAddr, FrameDecoder, FrameError, Interface, MsgType};

fn header(interf: Interface, msg_type: MsgType, subtype: u8, size: usize) -> player_proto::Header {
    let mut m = Message::new(DevAddr::local(interf, 0), msg_type, subtype, Body::Empty);
    m.header.size = size as u32;
    m.header
}

/// A device list body announcing `n` devices and carrying them all (16 bytes each).
fn devlist_body(n: u32) -> Bytes {
    let mut b = BytesMut::new();
    b.put_u32(n);
    b.put_u32(n);
    for i in 0..n {
        b.put_u32(0);
        b.put_u32(6665);
        b.put_u32(6);
        b.put_u32(i % 65536);
    }
    b.freeze()
}

#[test]
fn a_device_list_may_hold_4096_devices_and_no_more() {
    let ok = devlist_body(4096);
    let h = header(Interface::PLAYER, MsgType::Ack, 1, ok.len());
    let m = Message::decode(h, ok.clone()).unwrap();
    assert!(matches!(&m.body, Body::Player(Player::DevList(l)) if l.devices.len() == 4096));
    assert_eq!(&m.to_bytes()[40..], &ok[..]);

    let too_many = devlist_body(4097);
    let h = header(Interface::PLAYER, MsgType::Ack, 1, too_many.len());
    let err = Message::decode(h, too_many).unwrap_err();
    assert_eq!(
        err.fault,
        XdrFault::LengthAboveMax {
            length: 4097,
            max: 4096
        }
    );
    assert_eq!(err.offset, 4, "the length word");
    let text = err.to_string();
    assert!(text.contains("DevList.devices"), "{text}");
    assert!(
        text.contains("subtype 1") && text.contains("body byte 4"),
        "{text}"
    );
}

#[test]
fn a_lying_count_in_a_bounded_array_is_refused_before_allocating() {
    // Claims 2^32-1 devices and carries none: refused for the maximum, not the body size.
    let mut b = BytesMut::new();
    b.put_u32(u32::MAX);
    b.put_u32(u32::MAX);
    let h = header(Interface::PLAYER, MsgType::Ack, 1, 8);
    let err = Message::decode(h, b.freeze()).unwrap_err();
    assert!(matches!(
        err.fault,
        XdrFault::LengthAboveMax { max: 4096, .. }
    ));
}

/// A counted byte array body field: count, length, bytes, padding.
fn put_bytes(b: &mut BytesMut, bytes: &[u8]) {
    b.put_u32(bytes.len() as u32);
    b.put_u32(bytes.len() as u32);
    b.put_slice(bytes);
    b.put_bytes(0, (4 - bytes.len() % 4) % 4);
}

#[test]
fn driver_names_auth_keys_and_filter_parameters_have_their_maxima() {
    // DRIVERINFO: addr (16 bytes), then the name, at most 64 bytes.
    for (len, ok) in [(64, true), (65, false)] {
        let mut b = BytesMut::new();
        b.put_bytes(0, 16);
        put_bytes(&mut b, &vec![b'x'; len]);
        let h = header(Interface::PLAYER, MsgType::Ack, 2, b.len());
        let result = Message::decode(h, b.freeze());
        assert_eq!(result.is_ok(), ok, "driver name of {len} bytes");
        if let Err(e) = result {
            assert_eq!(e.offset, 20);
            assert_eq!(e.field.as_deref(), Some("DriverInfo.driver_name"));
        }
    }
    // AUTH: a key of at most 32 bytes.
    for (len, ok) in [(32, true), (33, false)] {
        let mut b = BytesMut::new();
        put_bytes(&mut b, &vec![7; len]);
        let h = header(Interface::PLAYER, MsgType::Req, 7, b.len());
        assert_eq!(Message::decode(h, b.freeze()).is_ok(), ok, "key of {len}");
    }
    // Laser SET_FILTER: filter type, then at most 8 float parameters.
    for (n, ok) in [(8u32, true), (9, false)] {
        let mut b = BytesMut::new();
        b.put_u32(1);
        b.put_u32(n);
        b.put_u32(n);
        b.put_bytes(0, 4 * n as usize);
        let h = header(Interface::LASER, MsgType::Req, 6, b.len());
        assert_eq!(Message::decode(h, b.freeze()).is_ok(), ok, "{n} parameters");
    }
}

#[test]
fn trailing_body_bytes_are_kept_and_re_encoded() {
    let scan = Message::typed(
        DevAddr::local(Interface::LASER, 0),
        MsgType::Data,
        Laser::Scan(LaserScan {
            ranges: vec![1.0, 2.0],
            ..LaserScan::default()
        }),
    );
    let mut wire = BytesMut::from(&scan.to_bytes()[..]);
    wire.put_slice(&[0xde, 0xad, 0xbe, 0xef]);
    let size = (wire.len() - 40) as u32;
    wire[36..40].copy_from_slice(&size.to_be_bytes());
    let wire = wire.freeze();

    let mut frames = FrameDecoder::default();
    frames.extend(&wire);
    let frame = frames.next_frame().unwrap().unwrap();
    let decoded = Message::decode(frame.header, frame.body).unwrap();
    assert_eq!(decoded.body, scan.body, "the typed body is still typed");
    assert_eq!(&decoded.trailing[..], &[0xde, 0xad, 0xbe, 0xef]);
    assert_eq!(decoded.to_bytes(), wire, "byte for byte");
}

#[test]
fn a_header_whose_interface_overflows_16_bits_is_a_framing_error() {
    let mut wire = BytesMut::from(
        &Message::new(
            DevAddr::local(Interface::LASER, 0),
            MsgType::Data,
            1,
            Body::Empty,
        )
        .to_bytes()[..],
    );
    wire[8..12].copy_from_slice(&0x0001_0006u32.to_be_bytes());
    let mut frames = FrameDecoder::default();
    frames.extend(&wire);
    let err = frames.next_frame().unwrap_err();
    assert!(matches!(err, FrameError::Header { offset: 0, .. }), "{err}");
    assert!(err.to_string().contains("interf"), "{err}");
}

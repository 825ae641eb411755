//! Every interface decoder on arbitrary bodies: the first four bytes pick interface, type and
//! subtype; the rest is the body. What decodes is also taken one step further where the crate
//! offers it (camera pixels to RGBA, map tiles inflated), as a viewer would.
#![no_main]

use bytes::Bytes;
use libfuzzer_sys::fuzz_target;
use player_proto::interfaces::camera::Camera;
use player_proto::interfaces::map::Map;
use player_proto::message::{Body, Message};
use player_proto::wire::{DevAddr, Header, Interface, MsgType};

fuzz_target!(|data: &[u8]| {
    if data.len() < 4 {
        return;
    }
    let interf = Interface(u16::from_be_bytes([data[0], data[1]]) % 70);
    let Some(msg_type) = MsgType::from_code(data[2] % 6 + 1) else {
        return;
    };
    let body = Bytes::copy_from_slice(&data[4..]);
    let header = Header {
        addr: DevAddr::local(interf, 0),
        msg_type,
        subtype: data[3],
        timestamp: 0.0,
        seq: 0,
        size: body.len() as u32,
    };
    if let Ok(message) = Message::decode(header, body) {
        let encoded = message.to_bytes();
        let again =
            Message::decode(message.header, encoded.slice(40..)).expect("own encoding decodes");
        assert_eq!(again.to_bytes(), encoded);
        match &message.body {
            Body::Camera(Camera::State(frame) | Camera::Image(frame)) => {
                let _ = frame.to_rgba();
            }
            Body::Map(Map::Tile(tile)) => {
                let _ = tile.cells();
            }
            _ => {}
        }
    }
});

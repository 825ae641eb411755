//! The fuzz seed corpus is worth its bytes: every `message_body` seed decodes to a typed body
//! under the header the fuzz target builds from its first four bytes (so the fuzzer starts
//! from real, deep messages rather than shallow errors), and re-encodes byte for byte.

use std::path::Path;

use bytes::Bytes;
use player_proto::message::{Body, Message};
use player_proto::wire::{DevAddr, Header, Interface, MsgType};

#[test]
fn every_message_body_seed_decodes_to_a_typed_body() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz/corpus/message_body");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).expect("the seed corpus") {
        let path = entry.unwrap().path();
        let data = std::fs::read(&path).unwrap();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        assert!(data.len() >= 4, "{name}: too short for the target's prefix");
        // Exactly as fuzz/fuzz_targets/message_body.rs reads it.
        let interf = Interface(u16::from_be_bytes([data[0], data[1]]) % 70);
        let msg_type = MsgType::from_code(data[2] % 6 + 1).unwrap();
        let body = Bytes::copy_from_slice(&data[4..]);
        let header = Header {
            addr: DevAddr::local(interf, 0),
            msg_type,
            subtype: data[3],
            timestamp: 0.0,
            seq: 0,
            size: body.len() as u32,
        };
        let message =
            Message::decode(header, body.clone()).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(
            !matches!(message.body, Body::Unknown(_)),
            "{name}: decodes to an unknown body"
        );
        assert!(message.trailing.is_empty(), "{name}: has trailing bytes");
        assert_eq!(&message.to_bytes()[40..], &body[..], "{name}");
        checked += 1;
    }
    assert!(checked >= 30, "only {checked} seeds");
}

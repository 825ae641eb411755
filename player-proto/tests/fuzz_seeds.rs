//! The fuzz seed corpus is worth its bytes: every `message_body` seed decodes to a typed body
//! under the header the fuzz target builds from its first four bytes (so the fuzzer starts
//! from real, deep messages rather than shallow errors), re-encodes byte for byte, and reads
//! in place as it decodes, whole and cut at every byte.

use std::path::Path;

use player_proto::fuzz_input::{message_parts, view_agrees};
use player_proto::message::{Body, Message};

#[test]
fn every_message_body_seed_decodes_to_a_typed_body() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz/corpus/message_body");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).expect("the seed corpus") {
        let path = entry.unwrap().path();
        let data = std::fs::read(&path).unwrap();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        // Exactly as fuzz/fuzz_targets/message_body.rs reads it.
        let (header, body) = message_parts(&data)
            .unwrap_or_else(|| panic!("{name}: too short for the target's prefix"));
        let message =
            Message::decode(header, body.clone()).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(
            !matches!(message.body, Body::Unknown(_)),
            "{name}: decodes to an unknown body"
        );
        assert!(message.trailing.is_empty(), "{name}: has trailing bytes");
        assert_eq!(&message.to_bytes()[40..], &body[..], "{name}");
        // Read in place, and cut anywhere: the view agrees with the decoder.
        for cut in 0..=body.len() {
            let mut short = header;
            short.size = cut as u32;
            let agrees = view_agrees(&short, &body.slice(..cut));
            assert_eq!(agrees, Ok(()), "{name} cut at {cut}");
        }
        checked += 1;
    }
    assert!(checked >= 30, "only {checked} seeds");
}

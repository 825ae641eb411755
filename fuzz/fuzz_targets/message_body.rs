//! Every interface decoder on arbitrary bodies: the first four bytes pick interface, type and
//! subtype; the rest is the body. What decodes is also taken one step further where the crate
//! offers it (camera pixels to RGBA, map tiles inflated), as a viewer would; and every body,
//! read in place as a view, gives what decoding it gives, or fails where decoding fails.
#![no_main]

use libfuzzer_sys::fuzz_target;
use player_proto::interfaces::camera::Camera;
use player_proto::interfaces::map::Map;
use player_proto::fuzz_input::{message_parts, view_agrees};
use player_proto::message::{Body, Message};

fuzz_target!(|data: &[u8]| {
    let Some((header, body)) = message_parts(data) else {
        return;
    };
    if let Err(difference) = view_agrees(&header, &body) {
        panic!("{header:?}: {difference}");
    }
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

//! Messages written out byte by byte, with a comment per field: each test states the wire form
//! from the protocol's tables by hand, so a codec that agrees with itself but not with Player
//! (a swapped field, a missing count word) fails here.

use player_proto::message::{Body, Message};
use player_proto::wire::FrameDecoder;

/// The bytes of annotated hex: everything after `//` on a line is a comment, whitespace is
/// ignored.
pub fn hex(text: &str) -> Vec<u8> {
    let digits: String = text
        .lines()
        .map(|line| line.split("//").next().unwrap_or(""))
        .flat_map(|code| code.split_whitespace())
        .collect();
    assert!(digits.len().is_multiple_of(2), "odd number of hex digits");
    (0..digits.len())
        .step_by(2)
        .map(|i| u8::from_str_radix(&digits[i..i + 2], 16).expect("hex digits"))
        .collect()
}

/// Frames exactly one message from annotated hex, decodes it to a typed body and checks that
/// it re-encodes to the same bytes.
pub fn message(text: &str) -> Message {
    let bytes = hex(text);
    let mut frames = FrameDecoder::default();
    frames.extend(&bytes);
    let frame = frames
        .next_frame()
        .expect("a valid frame")
        .expect("a whole message");
    assert_eq!(frames.buffered(), 0, "exactly one message");
    let message = Message::decode(frame.header, frame.body).expect("a decodable body");
    assert!(
        !matches!(message.body, Body::Unknown(_)),
        "{} decoded as unknown",
        message.header
    );
    assert!(message.trailing.is_empty(), "the body was read to its end");
    assert_eq!(&message.to_bytes()[..], &bytes[..], "re-encoding");
    message
}

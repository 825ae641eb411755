//! A recorded session as typed messages. Every message of both directions must decode to a
//! typed body (an `Unknown` would hide an interface we fail to read) and re-encode to the very
//! bytes that were recorded, so any golden test built on [`load`] checks the codec first.

use player_proto::capture::{Direction, parse_capture, stream};
use player_proto::message::{Body, Message};
use player_proto::wire::{Banner, FrameDecoder};

use super::captures::capture;

/// The Player version every recorded server announced.
pub const RECORDED_VERSION: &str = "3.1.1-dev";

/// Decodes one direction of a capture, checking the byte-identical round trip of every message.
fn decode_stream(name: &str, bytes: &[u8], dir: Direction) -> (Option<Banner>, Vec<Message>) {
    let mut frames = FrameDecoder::default();
    frames.extend(bytes);
    let banner = match dir {
        Direction::ServerToClient => Some(
            frames
                .take_banner()
                .expect("32 bytes of banner")
                .unwrap_or_else(|e| panic!("{name}: {e}")),
        ),
        Direction::ClientToServer => None,
    };
    let mut messages = Vec::new();
    while let Some(frame) = frames
        .next_frame()
        .unwrap_or_else(|e| panic!("{name} {dir}: {e}"))
    {
        let original = &bytes[frame.offset as usize..frame.offset as usize + 40 + frame.body.len()];
        let message = Message::decode(frame.header, frame.body.clone())
            .unwrap_or_else(|e| panic!("{name} {dir} at stream byte {}: {e}", frame.offset));
        assert!(
            !matches!(message.body, Body::Unknown(_)),
            "{name} {dir} at stream byte {}: {} stayed undecoded",
            frame.offset,
            message.header
        );
        assert_eq!(
            &message.to_bytes()[..],
            original,
            "{name} {dir} at byte {}: re-encoding differs",
            frame.offset
        );
        messages.push(message);
    }
    assert_eq!(
        frames.buffered(),
        0,
        "{name} {dir}: trailing partial message"
    );
    (banner, messages)
}

/// The server-to-client and client-to-server messages of capture `name`.
pub fn load(name: &str) -> (Vec<Message>, Vec<Message>) {
    let text = std::fs::read_to_string(capture(name)).unwrap();
    let chunks = parse_capture(&text).unwrap();
    let (banner, s2c) = decode_stream(
        name,
        &stream(&chunks, Direction::ServerToClient),
        Direction::ServerToClient,
    );
    assert_eq!(banner.unwrap().version, RECORDED_VERSION);
    let (_, c2s) = decode_stream(
        name,
        &stream(&chunks, Direction::ClientToServer),
        Direction::ClientToServer,
    );
    (s2c, c2s)
}

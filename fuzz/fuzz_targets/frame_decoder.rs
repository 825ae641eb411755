//! Any byte stream through banner, framing and decoding: no panic, no runaway allocation, and
//! whatever decodes re-encodes stably.
#![no_main]

use libfuzzer_sys::fuzz_target;
use player_proto::message::Message;
use player_proto::wire::FrameDecoder;

fuzz_target!(|data: &[u8]| {
    let mut frames = FrameDecoder::new(64 * 1024);
    // Feed in two uneven pieces to exercise partial frames.
    let split = data.len() / 3;
    frames.extend(&data[..split]);
    let _ = frames.take_banner();
    frames.extend(&data[split..]);
    while let Ok(Some(frame)) = frames.next_frame() {
        if let Ok(message) = Message::decode(frame.header, frame.body) {
            let once = message.to_bytes();
            let mut again = FrameDecoder::new(64 * 1024);
            again.extend(&once);
            let frame = again
                .next_frame()
                .expect("own encoding frames")
                .expect("whole");
            let twice = Message::decode(frame.header, frame.body).expect("own encoding decodes");
            assert_eq!(twice.to_bytes(), once);
        }
    }
});

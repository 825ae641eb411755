//! Property: every message re-encodes to the bytes it was decoded from.
//!
//! Bodies are generated for every variant of every interface's message set (through
//! `proptest-derive` on the macro-declared types), wrapped in a header of the right interface
//! and type, encoded, framed from the byte stream, decoded, and encoded again. Comparing bytes
//! rather than values keeps NaN payloads honest.

use proptest::prelude::*;

use crate::message::{Body, Message};
use crate::wire::{DevAddr, FrameDecoder, Interface, MessageClass, MsgType};

fn msg_type_for(class: MessageClass) -> BoxedStrategy<MsgType> {
    match class {
        MessageClass::Data => Just(MsgType::Data).boxed(),
        MessageClass::Command => Just(MsgType::Cmd).boxed(),
        MessageClass::Synch => Just(MsgType::Synch).boxed(),
        MessageClass::Request => {
            prop_oneof![Just(MsgType::Req), Just(MsgType::Ack), Just(MsgType::Nack)].boxed()
        }
    }
}

/// A message whose header agrees with its body.
fn message() -> impl Strategy<Value = Message> {
    (any::<Body>(), any::<DevAddr>(), any::<f64>(), any::<u32>()).prop_flat_map(
        |(body, addr, timestamp, seq)| {
            let (class, subtype) = body.kind().unwrap_or((MessageClass::Data, 0));
            let interf = match (&body, body.interface()) {
                (_, Some(interf)) => Just(interf).boxed(),
                // Plugin interface codes are never decoded, so the bytes stay unknown.
                (Body::Unknown(_), None) => (128u16..=255).prop_map(Interface).boxed(),
                (_, None) => any::<Interface>().boxed(),
            };
            let subtype = match body {
                Body::Unknown(_) | Body::Empty => any::<u8>().boxed(),
                _ => Just(subtype).boxed(),
            };
            (interf, subtype, msg_type_for(class)).prop_map(move |(interf, subtype, msg_type)| {
                let mut m =
                    Message::new(DevAddr { interf, ..addr }, msg_type, subtype, body.clone());
                m.header.timestamp = timestamp;
                m.header.seq = seq;
                m
            })
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn every_message_round_trips_through_a_byte_stream(original in message()) {
        let bytes = original.to_bytes();
        prop_assert_eq!(bytes.len(), original.encoded_len());

        let mut frames = FrameDecoder::default();
        frames.extend(&bytes);
        let frame = frames.next_frame().unwrap().expect("a whole frame");
        prop_assert_eq!(frames.buffered(), 0);

        let decoded = Message::decode(frame.header, frame.body).unwrap();
        prop_assert_eq!(decoded.body.kind(), original.body.kind());
        prop_assert_eq!(decoded.to_bytes(), bytes);
    }

    #[test]
    fn truncated_bodies_fail_cleanly(original in message(), cut in any::<prop::sample::Index>()) {
        let bytes = original.to_bytes();
        let body = bytes.slice(crate::wire::HEADER_LEN..);
        prop_assume!(!body.is_empty());
        let short = body.slice(..cut.index(body.len()));
        let mut header = original.header;
        header.size = short.len() as u32;
        // Either a clean error or (for a shorter valid prefix, or an unknown body) a message;
        // never a panic.
        let _ = Message::decode(header, short);
    }
}

//! Property: every message re-encodes to the bytes it was decoded from.
//!
//! Bodies are generated for every variant of every interface's message set (through
//! `proptest-derive` on the macro-declared types), wrapped in a header of the right interface
//! and type, encoded, framed from the byte stream, decoded, and encoded again. Comparing bytes
//! rather than values keeps NaN payloads honest.

use proptest::prelude::*;
use proptest::strategy::Union;

use crate::interfaces::kind::MessageKind;
use crate::interfaces::{self, universal::Universal};
use crate::message::{Body, Message, arbitrary_bytes};
use crate::wire::{DevAddr, FrameDecoder, Interface, MessageClass, MsgType};

/// The interfaces whose messages are generated, one boxed strategy each. Boxed, because the
/// derived `any::<Body>()` keeps every interface's value tree inline in one union: with 18
/// interfaces that outgrew a test thread's stack.
macro_rules! generated_interfaces {
    ($($code:ident => $set:ty),* $(,)?) => {
        const GENERATED: &[Interface] = &[$(Interface::$code),*];

        fn typed_bodies() -> Vec<BoxedStrategy<Body>> {
            vec![$(any::<$set>().prop_map(Body::from).boxed()),*]
        }
    };
}

generated_interfaces! {
    PLAYER => interfaces::player::Player,
    LASER => interfaces::laser::Laser,
    SONAR => interfaces::sonar::Sonar,
    POSITION2D => interfaces::position2d::Position2d,
    FIDUCIAL => interfaces::fiducial::Fiducial,
    CAMERA => interfaces::camera::Camera,
    RANGER => interfaces::ranger::Ranger,
    SIMULATION => interfaces::simulation::Simulation,
    BLOBFINDER => interfaces::blobfinder::Blobfinder,
    MAP => interfaces::map::Map,
    GRAPHICS2D => interfaces::graphics2d::Graphics2d,
    GRAPHICS3D => interfaces::graphics3d::Graphics3d,
    SPEECH => interfaces::speech::Speech,
    BUMPER => interfaces::bumper::Bumper,
    POWER => interfaces::power::Power,
    GRIPPER => interfaces::gripper::Gripper,
    LOCALIZE => interfaces::localize::Localize,
    PLANNER => interfaces::planner::Planner,
    PTZ => interfaces::ptz::Ptz,
    IR => interfaces::ir::Ir,
    POINTCLOUD3D => interfaces::pointcloud3d::Pointcloud3d,
    SPEECH_RECOGNITION => interfaces::speech_recognition::SpeechRecognition,
    LOG => interfaces::log::Log,
}

/// Any body: a typed one of a listed interface, a universal request, no body, or raw bytes.
fn body() -> impl Strategy<Value = Body> {
    let mut all = typed_bodies();
    all.push(Just(Body::Empty).boxed());
    all.push(any::<Universal>().prop_map(Body::Universal).boxed());
    all.push(arbitrary_bytes().prop_map(Body::Unknown).boxed());
    Union::new(all)
}

#[test]
fn every_decoded_interface_is_generated() {
    for (interf, name) in Interface::KNOWN {
        if !MessageKind::all_of(*interf).is_empty() {
            assert!(GENERATED.contains(interf), "{name} is not in the list");
        }
    }
}

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
    (body(), any::<DevAddr>(), any::<f64>(), any::<u32>()).prop_flat_map(
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
        if original.body.encoded_len() == 0 {
            // A body with no fields (the gripper's commands) is only its header on the wire:
            // it reads back as empty, and the header's subtype still names it.
            prop_assert_eq!(&decoded.body, &Body::Empty);
        } else {
            prop_assert_eq!(decoded.body.kind(), original.body.kind());
        }
        prop_assert_eq!(decoded.to_bytes(), bytes);
    }

    #[test]
    fn viewing_a_body_in_place_agrees_with_decoding_it(
        original in message(),
        cut in any::<prop::sample::Index>(),
    ) {
        let bytes = original.to_bytes();
        let body = bytes.slice(crate::wire::HEADER_LEN..);
        prop_assert_eq!(Body::view_agrees(&original.header, &body), Ok(()));
        // And where decoding fails, viewing fails alike: same fault, offset and field.
        let short = body.slice(..cut.index(body.len() + 1));
        let mut header = original.header;
        header.size = short.len() as u32;
        prop_assert_eq!(Body::view_agrees(&header, &short), Ok(()));
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

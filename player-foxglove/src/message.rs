//! One Foxglove message of any of the well-known schemas this crate produces, with its
//! schema and its protobuf encoding, so a file writer or a live server handles them alike.

use foxglove::Encode;
use foxglove::messages::{
    CompressedImage, FrameTransform, Grid, LaserScan, Log, PoseInFrame, RawImage, SceneUpdate,
};

/// A converted message and the topic it goes to.
#[derive(Debug, Clone, PartialEq)]
pub struct Output {
    pub topic: String,
    pub message: FoxgloveMessage,
}

macro_rules! foxglove_messages {
    ($($variant:ident),* $(,)?) => {
        /// A message in one of Foxglove's well-known schemas.
        #[derive(Debug, Clone, PartialEq)]
        pub enum FoxgloveMessage {
            $($variant($variant),)*
        }

        impl FoxgloveMessage {
            /// The schema (name `foxglove.…`, encoding `protobuf`, a file descriptor set).
            pub fn schema(&self) -> foxglove::Schema {
                match self {
                    $(FoxgloveMessage::$variant(_) => $variant::get_schema(),)*
                }
                .expect("well-known schemas have one")
            }

            /// The message's protobuf bytes.
            pub fn encode(&self) -> Vec<u8> {
                let mut out = Vec::new();
                match self {
                    $(FoxgloveMessage::$variant(m) => m.encode(&mut out),)*
                }
                .expect("a Vec grows as needed");
                out
            }
        }
    };
}

foxglove_messages!(
    LaserScan,
    PoseInFrame,
    FrameTransform,
    Grid,
    RawImage,
    CompressedImage,
    SceneUpdate,
    Log,
);

/// The message encoding of every schema here.
pub const MESSAGE_ENCODING: &str = "protobuf";

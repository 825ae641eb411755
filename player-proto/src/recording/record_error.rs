//! Why one record's payload (its checksum held) is not a record: the reader places it at a
//! byte offset ([`super::ReadError::BadRecord`]); a program can tell the cases apart without
//! reading the text.

use crate::wire::{BANNER_LEN, HeaderError};

#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum RecordError {
    #[error("payload of {len} bytes is shorter than the {fixed}-byte fixed part")]
    Short { len: usize, fixed: usize },
    #[error("unknown record kind {0}")]
    UnknownKind(u8),
    #[error("connection record without a port")]
    NoPort,
    #[error("{0} is not UTF-8")]
    NotUtf8(&'static str),
    #[error("banner of {len} bytes, not {BANNER_LEN}")]
    Banner { len: usize },
    #[error("unknown direction {0}")]
    UnknownDirection(u8),
    #[error("message of {len} bytes has no header")]
    NoHeader { len: usize },
    #[error("bad message header: {0}")]
    Header(#[from] HeaderError),
    #[error("message header announces {announced} body bytes, the record holds {held}")]
    BodySize { announced: u32, held: usize },
}

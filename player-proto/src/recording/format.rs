//! The recording format's fixed parts: the file header, the record framing and the four record
//! kinds (see `docs/RECORDING-FORMAT.md`, which this module implements).
//!
//! Every record is `length | payload | crc32(payload)`, so a reader can tell a whole record
//! from a torn one (a crash mid-write) or a damaged one without trusting anything else.

use std::time::{Duration, SystemTime, UNIX_EPOCH};

use bytes::Bytes;

use crate::capture::Direction;
use crate::wire::{BANNER_LEN, HEADER_LEN, Header};

use super::record_error::RecordError;

/// The first 8 bytes of every recording. The high first byte catches a file mangled by a 7-bit
/// or text-mode transfer, as PNG's signature does; the rest names the format to a person.
pub const MAGIC: [u8; 8] = *b"\x89PLAYREC";
/// The format version this crate writes and reads.
pub const VERSION: u32 = 1;
/// Magic, then the version as a big-endian u32.
pub const FILE_HEADER_LEN: usize = MAGIC.len() + 4;

/// The big-endian u32 before each payload: the payload's length.
pub const LENGTH_LEN: usize = 4;
/// The big-endian CRC-32 (ISO-HDLC, as zlib's) after each payload.
pub const CHECKSUM_LEN: usize = 4;
/// kind (1) | direction (1) | reserved, zero (2) | connection (4) | time in ns (8).
pub const FIXED_LEN: usize = 16;
/// The largest payload a reader accepts, so a damaged length field cannot make it allocate
/// without bound: 64 MiB, eight times the biggest body a Player client accepts by default.
pub const MAX_PAYLOAD: usize = 64 * 1024 * 1024;

/// Record kind codes (the payload's first byte).
pub mod kind {
    /// Declares a connection number: port (u16 BE), then the host, UTF-8.
    pub const CONNECTION: u8 = 1;
    /// The connection was established: the server's 32-byte banner.
    pub const OPENED: u8 = 2;
    /// One message: its 40-byte header and body exactly as they crossed the wire.
    pub const MESSAGE: u8 = 3;
    /// The connection ended: why, UTF-8.
    pub const CLOSED: u8 = 4;
}

/// Direction codes (the payload's second byte; 0 for records that are not messages).
const FROM_SERVER: u8 = 0;
const TO_SERVER: u8 = 1;

/// One record: when, on which connection, what.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    /// Nanoseconds since the Unix epoch: when the message was whole at the recording client.
    pub time_ns: u64,
    /// The connection's number, declared by an [`Event::Connection`] record.
    pub connection: u32,
    pub event: Event,
}

/// What a record holds.
#[derive(Debug, Clone, PartialEq)]
pub enum Event {
    Connection {
        host: String,
        port: u16,
    },
    Opened {
        banner: [u8; BANNER_LEN],
    },
    Message {
        direction: Direction,
        header: Header,
        /// Exactly `header.size` bytes.
        body: Bytes,
    },
    Closed {
        why: String,
    },
}

impl Record {
    /// The time as a [`SystemTime`].
    pub fn time(&self) -> SystemTime {
        UNIX_EPOCH + Duration::from_nanos(self.time_ns)
    }

    pub fn kind(&self) -> u8 {
        match self.event {
            Event::Connection { .. } => kind::CONNECTION,
            Event::Opened { .. } => kind::OPENED,
            Event::Message { .. } => kind::MESSAGE,
            Event::Closed { .. } => kind::CLOSED,
        }
    }

    /// The payload's fixed 16 bytes.
    pub fn fixed(&self) -> [u8; FIXED_LEN] {
        let direction = match &self.event {
            Event::Message {
                direction: Direction::ClientToServer,
                ..
            } => TO_SERVER,
            _ => FROM_SERVER,
        };
        let mut out = [0u8; FIXED_LEN];
        out[0] = self.kind();
        out[1] = direction;
        out[4..8].copy_from_slice(&self.connection.to_be_bytes());
        out[8..16].copy_from_slice(&self.time_ns.to_be_bytes());
        out
    }

    /// The payload after the fixed part, as up to two slices (a message's header, then its
    /// body), so the writer never copies a body to frame it.
    pub fn data(&self) -> (Vec<u8>, &[u8]) {
        match &self.event {
            Event::Connection { host, port } => {
                let mut head = port.to_be_bytes().to_vec();
                head.extend_from_slice(host.as_bytes());
                (head, &[])
            }
            Event::Opened { banner } => (banner.to_vec(), &[]),
            Event::Message { header, body, .. } => {
                let mut head = Vec::with_capacity(HEADER_LEN);
                header.encode(&mut head);
                (head, body)
            }
            Event::Closed { why } => (why.as_bytes().to_vec(), &[]),
        }
    }

    /// Payload length: fixed part and data.
    pub fn payload_len(&self) -> usize {
        FIXED_LEN
            + match &self.event {
                Event::Connection { host, .. } => 2 + host.len(),
                Event::Opened { .. } => BANNER_LEN,
                Event::Message { body, .. } => HEADER_LEN + body.len(),
                Event::Closed { why } => why.len(),
            }
    }

    /// Parses a payload whose checksum held. `Err` says what is wrong, for the reader to
    /// place at an offset.
    pub fn parse(payload: Bytes) -> Result<Record, RecordError> {
        if payload.len() < FIXED_LEN {
            return Err(RecordError::Short {
                len: payload.len(),
                fixed: FIXED_LEN,
            });
        }
        let word = |i: usize| u32::from_be_bytes(payload[i..i + 4].try_into().expect("4 bytes"));
        let connection = word(4);
        let time_ns = u64::from_be_bytes(payload[8..16].try_into().expect("8 bytes"));
        let data = payload.slice(FIXED_LEN..);
        let text = |bytes: &[u8], what: &'static str| {
            String::from_utf8(bytes.to_vec()).map_err(|_| RecordError::NotUtf8(what))
        };
        let event = match payload[0] {
            kind::CONNECTION => {
                if data.len() < 2 {
                    return Err(RecordError::NoPort);
                }
                let port = u16::from_be_bytes([data[0], data[1]]);
                let host = text(&data[2..], "connection host")?;
                Event::Connection { host, port }
            }
            kind::OPENED => Event::Opened {
                banner: data[..]
                    .try_into()
                    .map_err(|_| RecordError::Banner { len: data.len() })?,
            },
            kind::MESSAGE => {
                let direction = match payload[1] {
                    FROM_SERVER => Direction::ServerToClient,
                    TO_SERVER => Direction::ClientToServer,
                    other => return Err(RecordError::UnknownDirection(other)),
                };
                let header = Header::decode_slice(&data)
                    .ok_or(RecordError::NoHeader { len: data.len() })??;
                let body = data.slice(HEADER_LEN..);
                if body.len() != header.size as usize {
                    return Err(RecordError::BodySize {
                        announced: header.size,
                        held: body.len(),
                    });
                }
                Event::Message {
                    direction,
                    header,
                    body,
                }
            }
            kind::CLOSED => Event::Closed {
                why: text(&data, "close reason")?,
            },
            other => return Err(RecordError::UnknownKind(other)),
        };
        Ok(Record {
            time_ns,
            connection,
            event,
        })
    }
}

/// The time now in the format's unit.
pub fn now_ns() -> u64 {
    to_ns(SystemTime::now())
}

/// A time in the format's unit (0 before the epoch, saturating in the year 2554).
pub fn to_ns(time: SystemTime) -> u64 {
    time.duration_since(UNIX_EPOCH)
        .map_or(0, |d| u64::try_from(d.as_nanos()).unwrap_or(u64::MAX))
}

//! The 40-byte message header (`player_msghdr_t`) and message types.

use std::fmt;

use bytes::BufMut;

use super::address::DevAddr;
use super::xdr::Xdr;

/// The encoded header is always 40 bytes: every small field is widened to 4.
pub const HEADER_LEN: usize = 40;

/// `PLAYER_MSGTYPE_*`. Player 2.x/3.x define exactly these six; anything else is a protocol
/// error (Player 1.x's RESP_ERR = 7 belongs to a different wire protocol).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(any(test, feature = "proptest"), derive(proptest_derive::Arbitrary))]
pub enum MsgType {
    Data = 1,
    Cmd = 2,
    Req = 3,
    Ack = 4,
    Synch = 5,
    Nack = 6,
}

impl MsgType {
    pub fn from_code(code: u8) -> Option<MsgType> {
        Some(match code {
            1 => MsgType::Data,
            2 => MsgType::Cmd,
            3 => MsgType::Req,
            4 => MsgType::Ack,
            5 => MsgType::Synch,
            6 => MsgType::Nack,
            _ => return None,
        })
    }

    pub fn code(self) -> u8 {
        self as u8
    }

    /// Which body table a message of this type is decoded with.
    pub fn class(self) -> MessageClass {
        match self {
            MsgType::Data => MessageClass::Data,
            MsgType::Cmd => MessageClass::Command,
            MsgType::Req | MsgType::Ack | MsgType::Nack => MessageClass::Request,
            MsgType::Synch => MessageClass::Synch,
        }
    }

    /// Is this a reply (ACK or NACK) to a request?
    pub fn is_reply(self) -> bool {
        matches!(self, MsgType::Ack | MsgType::Nack)
    }
}

impl fmt::Display for MsgType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            MsgType::Data => "DATA",
            MsgType::Cmd => "CMD",
            MsgType::Req => "REQ",
            MsgType::Ack => "ACK",
            MsgType::Synch => "SYNCH",
            MsgType::Nack => "NACK",
        })
    }
}

/// The body table a message belongs to. Subtype numbers are unique only within a class: an
/// ACK or NACK is encoded with its request's structure, so the three share one table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MessageClass {
    Data,
    Command,
    Request,
    Synch,
}

impl MessageClass {
    /// The message type a message of this class is sent with by default: requests go out as
    /// REQ, the server answers with ACK or NACK.
    pub fn default_type(self) -> MsgType {
        match self {
            MessageClass::Data => MsgType::Data,
            MessageClass::Command => MsgType::Cmd,
            MessageClass::Request => MsgType::Req,
            MessageClass::Synch => MsgType::Synch,
        }
    }
}

/// `player_msghdr_t`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(any(test, feature = "proptest"), derive(proptest_derive::Arbitrary))]
pub struct Header {
    pub addr: DevAddr,
    pub msg_type: MsgType,
    pub subtype: u8,
    /// Seconds since the epoch (or simulation time, from Stage). Garbage in SYNCH messages.
    pub timestamp: f64,
    /// Unused by Player; kept so a message re-encodes byte for byte.
    pub seq: u32,
    /// Length of the encoded body that follows.
    pub size: u32,
}

/// Why 40 bytes are not a valid header.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum HeaderError {
    #[error("message type {0} is not one of Player's six (1 DATA .. 6 NACK)")]
    BadType(u32),
    /// A field Player declares narrower than its 4 wire bytes (interface and index are
    /// 16-bit, subtype 8-bit) holds a value that does not fit. Player would keep the low bits
    /// and so route the message to some other device; we refuse it, so that every header we
    /// accept re-encodes to the bytes it came from.
    #[error("header field {field} = {value} does not fit its {bits} bits")]
    FieldOutOfRange {
        field: &'static str,
        value: u32,
        bits: u32,
    },
}

impl Header {
    /// Decodes a header from exactly [`HEADER_LEN`] bytes.
    pub fn decode(raw: &[u8; HEADER_LEN]) -> Result<Header, HeaderError> {
        let word = |i: usize| u32::from_be_bytes(raw[i..i + 4].try_into().expect("4 bytes"));
        let type_code = word(16);
        let msg_type = u8::try_from(type_code)
            .ok()
            .and_then(MsgType::from_code)
            .ok_or(HeaderError::BadType(type_code))?;
        let narrow = |field: &'static str, at: usize, bits: u32| {
            let value = word(at);
            if value >> bits == 0 {
                Ok(value)
            } else {
                Err(HeaderError::FieldOutOfRange { field, value, bits })
            }
        };
        let interf = narrow("interf", 8, 16)? as u16;
        let index = narrow("index", 12, 16)? as u16;
        let subtype = narrow("subtype", 20, 8)? as u8;
        Ok(Header {
            addr: DevAddr {
                host: word(0),
                robot: word(4),
                interf: super::Interface(interf),
                index,
            },
            msg_type,
            subtype,
            timestamp: f64::from_be_bytes(raw[24..32].try_into().expect("8 bytes")),
            seq: word(32),
            size: word(36),
        })
    }

    /// Appends the 40-byte wire form.
    pub fn encode<B: BufMut>(&self, out: &mut B) {
        self.addr.encode(out);
        u32::from(self.msg_type.code()).encode(out);
        u32::from(self.subtype).encode(out);
        self.timestamp.encode(out);
        self.seq.encode(out);
        self.size.encode(out);
    }

    /// Decodes the header at the front of `body`-less bytes, for callers holding a slice.
    pub fn decode_slice(raw: &[u8]) -> Option<Result<Header, HeaderError>> {
        let raw: &[u8; HEADER_LEN] = raw.get(..HEADER_LEN)?.try_into().ok()?;
        Some(Header::decode(raw))
    }
}

impl fmt::Display for Header {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} {} subtype {} t={:.3} size {}",
            self.addr, self.msg_type, self.subtype, self.timestamp, self.size
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wire::Interface;

    /// The header of the protocol document's worked laser example (§2.4).
    const LASER_HEADER: [u8; 40] = [
        0x01, 0x00, 0x00, 0x7f, 0x00, 0x00, 0x1a, 0x09, 0x00, 0x00, 0x00, 0x06, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x41, 0xd9, 0x54, 0xfc, 0x40, 0x20,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x34,
    ];

    #[test]
    fn decodes_the_documented_header() {
        let h = Header::decode(&LASER_HEADER).unwrap();
        assert_eq!(h.addr.interf, Interface::LASER);
        assert_eq!(h.addr.robot, 6665);
        assert_eq!(h.msg_type, MsgType::Data);
        assert_eq!(h.subtype, 1);
        assert_eq!(h.timestamp, 1_700_000_000.5);
        assert_eq!(h.size, 52);
        let mut out = Vec::new();
        h.encode(&mut out);
        assert_eq!(out, LASER_HEADER);
    }

    #[test]
    fn refuses_unknown_types() {
        let mut raw = LASER_HEADER;
        raw[19] = 7;
        assert_eq!(Header::decode(&raw), Err(HeaderError::BadType(7)));
    }

    #[test]
    fn refuses_narrow_fields_that_overflow_instead_of_truncating() {
        for (at, field, bits) in [(8, "interf", 16), (12, "index", 16), (20, "subtype", 8)] {
            let mut raw = LASER_HEADER;
            raw[at..at + 4].copy_from_slice(&0x0001_0006u32.to_be_bytes());
            assert_eq!(
                Header::decode(&raw),
                Err(HeaderError::FieldOutOfRange {
                    field,
                    value: 0x0001_0006,
                    bits
                })
            );
        }
        // The widest values that fit are kept and re-encode identically.
        let mut raw = LASER_HEADER;
        raw[8..12].copy_from_slice(&[0, 0, 0xff, 0xff]);
        raw[20..24].copy_from_slice(&[0, 0, 0, 0xff]);
        let mut out = Vec::new();
        Header::decode(&raw).unwrap().encode(&mut out);
        assert_eq!(out, raw);
    }
}

//! How the `message_body` fuzz target turns its bytes into a message to decode, and what it
//! checks of views. It lives here, not in the target, so that the test of the target's seed
//! corpus reads seeds exactly as the fuzzer does.

use bytes::Bytes;

use crate::view_disagreement::ViewDisagreement;
use crate::wire::{DevAddr, Header, Interface, MsgType};

/// The header and body a fuzz input stands for: interface (2 bytes, modulo 70, so that every
/// interface is reachable), message type (1 byte, modulo the six types), subtype (1 byte),
/// then the body. `None` for inputs shorter than those four bytes.
pub fn message_parts(data: &[u8]) -> Option<(Header, Bytes)> {
    let [i0, i1, kind, subtype, body @ ..] = data else {
        return None;
    };
    let body = Bytes::copy_from_slice(body);
    let header = Header {
        addr: DevAddr::local(Interface(u16::from_be_bytes([*i0, *i1]) % 70), 0),
        msg_type: MsgType::from_code(kind % 6 + 1)?,
        subtype: *subtype,
        timestamp: 0.0,
        seq: 0,
        size: u32::try_from(body.len()).ok()?,
    };
    Some((header, body))
}

/// Whether reading `body` in place ([`crate::wire::xdr_view`]) agrees with decoding it: the
/// same value, or the same error at the same byte. A description of the difference if not.
pub fn view_agrees(header: &Header, body: &Bytes) -> Result<(), ViewDisagreement> {
    crate::message::Body::view_agrees(header, body)
}

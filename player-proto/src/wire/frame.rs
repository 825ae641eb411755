//! Framing: cutting a byte stream into messages (a 40-byte header, then exactly `size` body
//! bytes) without trusting the sender.

use bytes::{Buf, Bytes, BytesMut};

use super::banner::{BANNER_LEN, Banner, BannerError};
use super::header::{HEADER_LEN, Header, HeaderError};

/// The default largest body accepted: Player's nominal 8 MiB message size, which holds a
/// 1920×1080 RGB camera frame (6 220 800 bytes) with room to spare.
pub const DEFAULT_MAX_BODY: usize = 8 * 1024 * 1024;

/// How much room the receive buffer is given at a time (a body longer than this gets room for
/// all of it at once). Small, because bodies are split off the buffer without copying: a
/// stored message keeps its whole block alive, and with 64 KiB blocks a thousand connections
/// each holding two newest scans kept about 130 MB for 4 MB of messages.
pub const RECEIVE_CHUNK: usize = 8 * 1024;

/// One message cut from the stream, body not yet decoded.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    pub header: Header,
    /// Exactly `header.size` bytes.
    pub body: Bytes,
    /// Where the header started, counted from the start of the stream (banner included).
    pub offset: u64,
}

/// Why the stream cannot be framed any further.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FrameError {
    #[error("bad banner: {0}")]
    Banner(#[from] BannerError),
    #[error("bad header at stream byte {offset}: {source}")]
    Header { offset: u64, source: HeaderError },
    #[error(
        "message at stream byte {offset} ({header}) announces a {size}-byte body, above the {limit}-byte limit"
    )]
    TooLarge {
        offset: u64,
        header: Header,
        size: u64,
        limit: usize,
    },
}

/// Incremental frame decoder: feed it whatever arrived, take whole frames out.
///
/// A header whose `size` exceeds the limit is refused before a single body byte is buffered,
/// so a lying size field cannot make us allocate. Bodies are split off the receive buffer as
/// [`Bytes`] without copying.
#[derive(Debug)]
pub struct FrameDecoder {
    buf: BytesMut,
    max_body: usize,
    /// Stream offset of `buf[0]`.
    consumed: u64,
    /// A header already read whose body has not fully arrived.
    pending: Option<Header>,
}

impl Default for FrameDecoder {
    fn default() -> Self {
        Self::new(DEFAULT_MAX_BODY)
    }
}

impl FrameDecoder {
    pub fn new(max_body: usize) -> Self {
        Self {
            buf: BytesMut::with_capacity(RECEIVE_CHUNK),
            max_body,
            consumed: 0,
            pending: None,
        }
    }

    pub fn max_body(&self) -> usize {
        self.max_body
    }

    /// Appends received bytes.
    pub fn extend(&mut self, data: &[u8]) {
        self.buf.extend_from_slice(data);
    }

    /// The receive buffer, to read into directly (e.g. with `read_buf`).
    pub fn buffer_mut(&mut self) -> &mut BytesMut {
        &mut self.buf
    }

    /// Bytes received and not yet returned as frames.
    pub fn buffered(&self) -> usize {
        self.buf.len()
    }

    /// Stream offset of the next unread byte.
    pub fn offset(&self) -> u64 {
        self.consumed
    }

    /// Takes the 32-byte banner off the front of the stream, once enough has arrived.
    pub fn take_banner(&mut self) -> Option<Result<Banner, BannerError>> {
        if self.buf.len() < BANNER_LEN {
            return None;
        }
        let raw: [u8; BANNER_LEN] = self.buf[..BANNER_LEN].try_into().expect("32 bytes");
        self.buf.advance(BANNER_LEN);
        self.consumed += BANNER_LEN as u64;
        Some(Banner::parse(&raw))
    }

    /// The next whole frame, `Ok(None)` if more bytes are needed.
    pub fn next_frame(&mut self) -> Result<Option<Frame>, FrameError> {
        let header = match self.pending {
            Some(header) => header,
            None => {
                let Some(parsed) = Header::decode_slice(&self.buf) else {
                    return Ok(None);
                };
                let header = parsed.map_err(|source| FrameError::Header {
                    offset: self.consumed,
                    source,
                })?;
                if header.size as usize > self.max_body {
                    return Err(FrameError::TooLarge {
                        offset: self.consumed,
                        header,
                        size: u64::from(header.size),
                        limit: self.max_body,
                    });
                }
                self.pending = Some(header);
                header
            }
        };
        let total = HEADER_LEN + header.size as usize;
        if self.buf.len() < total {
            // Make room once for the whole body instead of growing step by step.
            self.buf.reserve(total - self.buf.len());
            return Ok(None);
        }
        let offset = self.consumed;
        self.buf.advance(HEADER_LEN);
        let body = self.buf.split_to(header.size as usize).freeze();
        self.consumed += total as u64;
        self.pending = None;
        Ok(Some(Frame {
            header,
            body,
            offset,
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wire::{DevAddr, Interface, MsgType};

    fn frame_bytes(size: u32, body: &[u8]) -> Vec<u8> {
        let header = Header {
            addr: DevAddr::local(Interface::LASER, 0),
            msg_type: MsgType::Data,
            subtype: 1,
            timestamp: 0.0,
            seq: 0,
            size,
        };
        let mut out = Vec::new();
        header.encode(&mut out);
        out.extend_from_slice(body);
        out
    }

    #[test]
    fn frames_arrive_byte_by_byte() {
        let mut stream = frame_bytes(4, &[1, 2, 3, 4]);
        stream.extend(frame_bytes(0, &[]));
        let mut decoder = FrameDecoder::default();
        let mut frames = Vec::new();
        for byte in stream {
            decoder.extend(&[byte]);
            while let Some(frame) = decoder.next_frame().unwrap() {
                frames.push(frame);
            }
        }
        assert_eq!(frames.len(), 2);
        assert_eq!(&frames[0].body[..], &[1, 2, 3, 4]);
        assert_eq!(frames[1].offset, 44);
        assert_eq!(decoder.buffered(), 0);
    }

    #[test]
    fn lying_size_is_refused_before_allocating() {
        let mut decoder = FrameDecoder::new(1024);
        decoder.extend(&frame_bytes(u32::MAX, &[]));
        let err = decoder.next_frame().unwrap_err();
        assert!(matches!(err, FrameError::TooLarge { size, .. } if size == u64::from(u32::MAX)));
        assert!(decoder.buffer_mut().capacity() < 1024 * 1024);
    }

    #[test]
    fn bad_type_names_the_offset() {
        let mut bytes = frame_bytes(0, &[]);
        bytes[19] = 9;
        let mut decoder = FrameDecoder::default();
        decoder.extend(&[0; 32]);
        decoder.extend(&bytes);
        assert!(decoder.take_banner().unwrap().is_err());
        assert_eq!(
            decoder.next_frame().unwrap_err(),
            FrameError::Header {
                offset: 32,
                source: HeaderError::BadType(9)
            }
        );
    }
}

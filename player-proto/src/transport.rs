//! Messages over an async byte stream (a TCP socket): the one place where reading and writing
//! meet framing, shared by the client and the server.
//!
//! A body that fails to decode does not end the stream — framing is intact, so the reader
//! reports the bad message and the caller carries on. A broken frame (bad header, lying size)
//! or a peer closing mid-message does end it, with the stream offset in the error.

use std::borrow::Borrow;
use std::io;

use bytes::BytesMut;
use tokio::io::{AsyncRead, AsyncReadExt, AsyncWrite, AsyncWriteExt};

use crate::message::{DecodeError, Message};
use crate::wire::{Banner, Frame, FrameDecoder, FrameError, RECEIVE_CHUNK};

/// What can go wrong reading a stream of messages.
#[derive(Debug, thiserror::Error)]
pub enum TransportError {
    #[error("connection error: {0}")]
    Io(#[from] io::Error),
    #[error(transparent)]
    Frame(#[from] FrameError),
    #[error(
        "peer closed the connection in the middle of a message ({buffered} bytes of it at stream byte {offset})"
    )]
    ClosedMidMessage { offset: u64, buffered: usize },
    #[error("peer closed the connection before sending its banner")]
    NoBanner,
}

/// What a read produced.
#[derive(Debug)]
pub enum Incoming {
    Message(Message),
    /// A well-framed message whose body did not decode; the stream goes on.
    Undecodable(DecodeError),
    /// The peer closed the connection cleanly, between messages.
    Closed,
}

impl Incoming {
    /// What a frame read by [`MessageReader::read_frame`] is (`None`: a clean close).
    pub fn decode(frame: Option<Frame>) -> Incoming {
        match frame {
            None => Incoming::Closed,
            Some(frame) => match Message::decode(frame.header, frame.body) {
                Ok(message) => Incoming::Message(message),
                Err(err) => Incoming::Undecodable(err),
            },
        }
    }
}

/// Reads messages from a byte stream.
#[derive(Debug)]
pub struct MessageReader<R> {
    inner: R,
    frames: FrameDecoder,
}

impl<R: AsyncRead + Unpin> MessageReader<R> {
    pub fn new(inner: R, frames: FrameDecoder) -> Self {
        Self { inner, frames }
    }

    /// Reads the 32-byte banner a server sends first.
    pub async fn read_banner(&mut self) -> Result<Banner, TransportError> {
        loop {
            if let Some(banner) = self.frames.take_banner() {
                return Ok(banner.map_err(FrameError::from)?);
            }
            if self.fill().await? == 0 {
                return Err(TransportError::NoBanner);
            }
        }
    }

    /// The next framed message, body not decoded; `None` on a clean close.
    pub async fn read_frame(&mut self) -> Result<Option<Frame>, TransportError> {
        loop {
            if let Some(frame) = self.frames.next_frame()? {
                return Ok(Some(frame));
            }
            if self.fill().await? == 0 {
                return match self.frames.buffered() {
                    0 => Ok(None),
                    buffered => Err(TransportError::ClosedMidMessage {
                        offset: self.frames.offset(),
                        buffered,
                    }),
                };
            }
        }
    }

    /// The next message, decoded.
    pub async fn read(&mut self) -> Result<Incoming, TransportError> {
        Ok(Incoming::decode(self.read_frame().await?))
    }

    /// Bytes of the stream consumed so far.
    pub fn offset(&self) -> u64 {
        self.frames.offset()
    }

    pub fn get_ref(&self) -> &R {
        &self.inner
    }

    async fn fill(&mut self) -> io::Result<usize> {
        let buf: &mut BytesMut = self.frames.buffer_mut();
        if buf.capacity() - buf.len() < 4096 {
            buf.reserve(RECEIVE_CHUNK);
        }
        self.inner.read_buf(buf).await
    }
}

/// Encodes `message` into `scratch` (cleared first, reused to avoid an allocation per message)
/// and writes it in one call, so a message is never interleaved with another writer's.
pub async fn write_message<W: AsyncWrite + Unpin>(
    out: &mut W,
    message: &Message,
    scratch: &mut BytesMut,
) -> io::Result<()> {
    scratch.clear();
    scratch.reserve(message.encoded_len());
    message.encode(scratch);
    out.write_all(scratch).await
}

/// How many bytes [`write_messages`] gathers before it writes: a burst of small messages
/// leaves in one call, a backlog of big ones in a few.
const GATHER_BYTES: usize = 256 * 1024;

/// Encodes `messages` back to back into `scratch` and writes them in as few calls as
/// [`GATHER_BYTES`] allows — one for a step's pose and scan — so that the peer gets one
/// segment and one wake-up, not one per message. Messages are never split between calls
/// except when one alone exceeds the gathering size.
pub async fn write_messages<W: AsyncWrite + Unpin, M: Borrow<Message>>(
    out: &mut W,
    messages: &[M],
    scratch: &mut BytesMut,
) -> io::Result<()> {
    scratch.clear();
    for message in messages {
        let message: &Message = message.borrow();
        let len = message.encoded_len();
        if !scratch.is_empty() && scratch.len() + len > GATHER_BYTES {
            out.write_all(scratch).await?;
            scratch.clear();
        }
        scratch.reserve(len);
        message.encode(scratch);
    }
    if !scratch.is_empty() {
        out.write_all(scratch).await?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interfaces::laser::{Laser, LaserScan};
    use crate::wire::{DevAddr, Interface, MsgType};

    fn scan_message() -> Message {
        let scan = LaserScan {
            ranges: vec![1.0, 2.0, 3.0],
            ..LaserScan::default()
        };
        Message::typed(
            DevAddr::local(Interface::LASER, 0),
            MsgType::Data,
            Laser::Scan(scan),
        )
    }

    #[tokio::test]
    async fn reads_what_was_written_then_a_clean_close() {
        let (mut a, b) = tokio::io::duplex(64);
        let writer = tokio::spawn(async move {
            let mut scratch = BytesMut::new();
            a.write_all(&Banner::new("3.1.1-dev").unwrap().to_bytes())
                .await
                .unwrap();
            for _ in 0..3 {
                write_message(&mut a, &scan_message(), &mut scratch)
                    .await
                    .unwrap();
            }
        });
        let mut reader = MessageReader::new(b, FrameDecoder::default());
        assert_eq!(reader.read_banner().await.unwrap().version, "3.1.1-dev");
        for _ in 0..3 {
            match reader.read().await.unwrap() {
                Incoming::Message(m) => assert_eq!(m, scan_message()),
                other => panic!("expected a message, got {other:?}"),
            }
        }
        writer.await.unwrap();
        assert!(matches!(reader.read().await.unwrap(), Incoming::Closed));
    }

    /// Counts the write calls that reach it.
    #[derive(Default)]
    struct CountingSink {
        bytes: Vec<u8>,
        writes: usize,
    }

    impl AsyncWrite for CountingSink {
        fn poll_write(
            mut self: std::pin::Pin<&mut Self>,
            _: &mut std::task::Context<'_>,
            buf: &[u8],
        ) -> std::task::Poll<io::Result<usize>> {
            self.writes += 1;
            self.bytes.extend_from_slice(buf);
            std::task::Poll::Ready(Ok(buf.len()))
        }
        fn poll_flush(
            self: std::pin::Pin<&mut Self>,
            _: &mut std::task::Context<'_>,
        ) -> std::task::Poll<io::Result<()>> {
            std::task::Poll::Ready(Ok(()))
        }
        fn poll_shutdown(
            self: std::pin::Pin<&mut Self>,
            _: &mut std::task::Context<'_>,
        ) -> std::task::Poll<io::Result<()>> {
            std::task::Poll::Ready(Ok(()))
        }
    }

    #[tokio::test]
    async fn a_burst_leaves_in_one_write_and_a_backlog_in_a_few_whole_messages_each() {
        let small = [scan_message(), scan_message()];
        let mut sink = CountingSink::default();
        let mut scratch = BytesMut::new();
        write_messages(&mut sink, &small, &mut scratch)
            .await
            .unwrap();
        assert_eq!(sink.writes, 1);

        // 300 scans of 1 000 beams (some 4 KiB each): more than one gathering's worth.
        let big = Message::typed(
            DevAddr::local(Interface::LASER, 0),
            MsgType::Data,
            Laser::Scan(LaserScan {
                ranges: vec![1.5; 1000],
                ..LaserScan::default()
            }),
        );
        let backlog = vec![big.clone(); 300];
        let mut sink = CountingSink::default();
        write_messages(&mut sink, &backlog, &mut scratch)
            .await
            .unwrap();
        let total = backlog.len() * big.encoded_len();
        assert_eq!(sink.bytes.len(), total);
        assert_eq!(
            sink.writes,
            total.div_ceil(GATHER_BYTES / big.encoded_len() * big.encoded_len())
        );
        let mut reader = MessageReader::new(&sink.bytes[..], FrameDecoder::default());
        for _ in 0..backlog.len() {
            match reader.read().await.unwrap() {
                Incoming::Message(m) => assert_eq!(m, big),
                other => panic!("expected a message, got {other:?}"),
            }
        }
        assert!(matches!(reader.read().await.unwrap(), Incoming::Closed));
    }

    #[tokio::test]
    async fn half_a_message_then_close_is_an_error_with_the_offset() {
        let bytes = scan_message().to_bytes();
        let (mut a, b) = tokio::io::duplex(1024);
        a.write_all(&bytes[..50]).await.unwrap();
        drop(a);
        let mut reader = MessageReader::new(b, FrameDecoder::default());
        let err = reader.read().await.unwrap_err();
        assert!(
            matches!(
                err,
                TransportError::ClosedMidMessage {
                    offset: 0,
                    buffered: 50
                }
            ),
            "{err}"
        );
    }

    #[tokio::test]
    async fn an_undecodable_body_does_not_end_the_stream() {
        let good = scan_message().to_bytes();
        let mut bad = good.to_vec();
        // ranges count and length claim 1000 floats that are not there.
        bad[56..64].copy_from_slice(&[0, 0, 3, 0xe8, 0, 0, 3, 0xe8]);
        let (mut a, b) = tokio::io::duplex(4096);
        a.write_all(&bad).await.unwrap();
        a.write_all(&good).await.unwrap();
        drop(a);
        let mut reader = MessageReader::new(b, FrameDecoder::default());
        match reader.read().await.unwrap() {
            Incoming::Undecodable(e) => {
                assert!(e.to_string().contains("laser DATA subtype 1"), "{e}")
            }
            other => panic!("expected an undecodable message, got {other:?}"),
        }
        assert!(matches!(reader.read().await.unwrap(), Incoming::Message(_)));
    }
}

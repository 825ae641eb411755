//! A viewer's WebSocket, as every front serves one: the listener, a burst sent within a
//! deadline, and the close — with its code typed and its reason cut to fit.
//!
//! One rule for a viewer that stops reading, whatever the front: a burst that has not left
//! within [`STALLED_AFTER`] closes the viewer (1008, "not reading for 30 s"). Until then it
//! costs only its bounded queue (the page's broadcast position, Foxglove's outbox), so a
//! paused viewer — a debugger, a hidden tab, a laptop's lid closed a moment — is not dropped
//! for a short pause, and nobody else ever waits for it.

use std::net::SocketAddr;
use std::time::Duration;

use axum::extract::ws::{CloseFrame, Message, Utf8Bytes, WebSocket};
use futures_util::SinkExt;
use futures_util::stream::SplitSink;

/// How long one burst may take to leave before its viewer is taken for gone.
pub const STALLED_AFTER: Duration = Duration::from_secs(30);

/// How long the close frame may take: a viewer that is not reading may not get it either.
const CLOSE_WITHIN: Duration = Duration::from_millis(100);

/// The most bytes a close frame's reason holds (RFC 6455: 125 less the code's two).
pub const CLOSE_REASON_MAX: usize = 123;

/// The sending half of a viewer's socket.
pub type Out = SplitSink<WebSocket, Message>;

/// Why a viewer's socket is closed, as RFC 6455 numbers it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum CloseCode {
    /// 1001: the server stops (the front was stopped or dropped).
    GoingAway,
    /// 1002: the viewer broke the protocol.
    Protocol,
    /// 1008: the viewer broke the server's rules (it stopped reading).
    Policy,
    /// 1009: the viewer sent a message over the limit.
    TooBig,
}

impl CloseCode {
    pub fn code(self) -> u16 {
        match self {
            CloseCode::GoingAway => 1001,
            CloseCode::Protocol => 1002,
            CloseCode::Policy => 1008,
            CloseCode::TooBig => 1009,
        }
    }

    /// The code for a socket that failed with `error`: 1009 for a message or frame over the
    /// limit, else 1002. Told by the error's type, not its words.
    pub fn of_error(error: &axum::Error) -> CloseCode {
        let cause = std::error::Error::source(error);
        match cause.and_then(|c| c.downcast_ref::<tungstenite::Error>()) {
            Some(tungstenite::Error::Capacity(_)) => CloseCode::TooBig,
            _ => CloseCode::Protocol,
        }
    }
}

/// Why a burst did not leave.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SendError {
    #[error("cannot send: {0}")]
    Failed(#[source] axum::Error),
    /// The viewer read nothing for [`STALLED_AFTER`]: it was closed.
    #[error("not reading for {} s", .0.as_secs())]
    Stalled(Duration),
}

/// A listener on `addr` whose connections start with a kernel send buffer of `send_buffer`
/// bytes (Linux hands the listener's to each accepted socket): a viewer that stops reading
/// fills it in a moment instead of holding megabytes of stale frames. Its backlog takes
/// hundreds of viewers connecting at once (a class told the address at the same moment).
pub fn listen(addr: SocketAddr, send_buffer: usize) -> std::io::Result<std::net::TcpListener> {
    use socket2::{Domain, Socket, Type};
    let socket = Socket::new(Domain::for_address(addr), Type::STREAM, None)?;
    socket.set_reuse_address(true)?;
    socket.set_send_buffer_size(send_buffer)?;
    socket.bind(&addr.into())?;
    socket.listen(1024)?;
    socket.set_nonblocking(true)?;
    Ok(socket.into())
}

/// Writes `messages` and flushes them once, all within [`STALLED_AFTER`]; a viewer that
/// takes longer is closed ([`CloseCode::Policy`]) and [`SendError::Stalled`] returned.
pub async fn send_within(
    out: &mut Out,
    messages: impl IntoIterator<Item = Message>,
) -> Result<(), SendError> {
    let write = async {
        for message in messages {
            out.feed(message).await?;
        }
        out.flush().await
    };
    match tokio::time::timeout(STALLED_AFTER, write).await {
        Ok(Ok(())) => Ok(()),
        Ok(Err(e)) => Err(SendError::Failed(e)),
        Err(_) => {
            let stalled = SendError::Stalled(STALLED_AFTER);
            close(out, CloseCode::Policy, &stalled.to_string()).await;
            Err(stalled)
        }
    }
}

/// Says why the socket closes, best effort, within a moment.
pub async fn close(out: &mut Out, code: CloseCode, why: &str) {
    let frame = CloseFrame {
        code: code.code(),
        reason: Utf8Bytes::from(close_reason(why)),
    };
    let _ = tokio::time::timeout(CLOSE_WITHIN, out.send(Message::Close(Some(frame)))).await;
}

/// `why`, cut at a character's edge to what a close frame holds.
pub fn close_reason(why: &str) -> &str {
    let mut end = why.len().min(CLOSE_REASON_MAX);
    while !why.is_char_boundary(end) {
        end -= 1;
    }
    &why[..end]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reason_is_cut_to_a_close_frame_at_a_character_edge() {
        assert_eq!(close_reason("short"), "short");
        let long = "é".repeat(100);
        let cut = close_reason(&long);
        assert_eq!(
            cut.len(),
            122,
            "61 two-byte characters, not half of the 62nd"
        );
        assert_eq!(close_reason(&"a".repeat(200)).len(), CLOSE_REASON_MAX);
    }

    #[test]
    fn a_message_over_the_limit_closes_with_1009_and_anything_else_with_1002() {
        let too_big =
            tungstenite::Error::Capacity(tungstenite::error::CapacityError::MessageTooLong {
                size: 2,
                max_size: 1,
            });
        assert_eq!(
            CloseCode::of_error(&axum::Error::new(too_big)),
            CloseCode::TooBig
        );
        let broken = tungstenite::Error::Protocol(
            tungstenite::error::ProtocolError::UnmaskedFrameFromClient,
        );
        assert_eq!(
            CloseCode::of_error(&axum::Error::new(broken)),
            CloseCode::Protocol
        );
        assert_eq!(CloseCode::TooBig.code(), 1009);
    }
}

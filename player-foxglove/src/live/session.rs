//! One viewer's WebSocket: `serverInfo` and the channels so far, then whatever its outbox
//! gathers, a burst in one write; its requests carried out, a bad one answered with an error
//! `status` and the connection kept. A viewer whose write does not complete within
//! [`SEND_TIMEOUT`] is not reading and is closed; until then it loses its oldest messages,
//! not its connection.

use std::net::SocketAddr;
use std::sync::Arc;
use std::time::Duration;

use axum::extract::ws::{CloseFrame, Message, Utf8Bytes, WebSocket};
use futures_util::stream::SplitSink;
use futures_util::{SinkExt, StreamExt};

use super::hub::{Hub, ViewerId};
use super::outbox::{Batch, Outbox};
use super::wire::{self, Level, Request};

/// How long one burst may take to leave: a viewer that reads nothing for this long is
/// closed. Long, since a paused viewer (a debugger, a hidden tab) costs only its bounded
/// outbox meanwhile.
pub const SEND_TIMEOUT: Duration = Duration::from_secs(30);

/// WebSocket close codes: 1002 protocol error, 1008 policy violation (a viewer that is not
/// reading), 1009 message too big.
const CLOSE_PROTOCOL: u16 = 1002;
const CLOSE_POLICY: u16 = 1008;
const CLOSE_TOO_BIG: u16 = 1009;

type Out = SplitSink<WebSocket, Message>;

/// Serves one viewer until it or the server goes.
pub async fn serve_viewer(socket: WebSocket, from: SocketAddr, hub: Arc<Hub>, session_id: String) {
    let outbox = Arc::new(Outbox::default());
    outbox.push_control(wire::server_info("player-relay", &session_id));
    let viewer = hub.join(outbox.clone());
    let (mut out, mut incoming) = socket.split();
    let why = loop {
        tokio::select! {
            batch = outbox.next() => {
                let Some(batch) = batch else {
                    close(&mut out, CLOSE_POLICY, "the server stops or the viewer lags").await;
                    break "closed by the server".to_string();
                };
                if let Err(why) = send(&mut out, batch).await {
                    break why;
                }
            }
            message = incoming.next() => match message {
                Some(Ok(Message::Text(text))) => request(&hub, &outbox, viewer, &text),
                Some(Ok(Message::Binary(_))) => outbox.push_control(wire::status(
                    Level::Error,
                    "Invalid message: binary messages need the clientPublish or services \
                     capability, which this server does not advertise",
                )),
                Some(Ok(Message::Ping(_) | Message::Pong(_))) => {}
                Some(Ok(Message::Close(_))) | None => break "the viewer closed".to_string(),
                Some(Err(e)) => {
                    let why = format!("the socket failed: {e}");
                    close(&mut out, close_code(&e), &why).await;
                    break why;
                }
            },
        }
    };
    hub.leave(viewer);
    tracing::debug!(viewer, %from, "Foxglove viewer gone: {why}");
}

/// Carries out one text request; what is wrong with it goes back as an error status.
fn request(hub: &Hub, outbox: &Outbox, viewer: ViewerId, text: &str) {
    let outcome = wire::parse_request(text).and_then(|request| {
        let mut errors = Vec::new();
        match request {
            Request::Subscribe(subscriptions) => {
                for (subscription, channel) in subscriptions {
                    errors.extend(hub.subscribe(viewer, subscription, channel).err());
                }
            }
            Request::Unsubscribe(subscriptions) => {
                for subscription in subscriptions {
                    errors.extend(hub.unsubscribe(viewer, subscription).err());
                }
            }
        }
        match errors.is_empty() {
            true => Ok(()),
            false => Err(errors.join("; ")),
        }
    });
    if let Err(why) = outcome {
        outbox.push_control(wire::status(Level::Error, &why));
    }
}

/// Writes a batch and flushes it once, all within [`SEND_TIMEOUT`].
async fn send(out: &mut Out, batch: Batch) -> Result<(), String> {
    if batch.dropped > 0 {
        tracing::debug!(dropped = batch.dropped, "a Foxglove viewer fell behind");
    }
    let write = async {
        for text in batch.control {
            out.feed(Message::Text(text)).await?;
        }
        for data in batch.data {
            let frame = wire::message_data(data.subscription, data.log_time, &data.payload);
            out.feed(Message::Binary(frame)).await?;
        }
        out.flush().await
    };
    match tokio::time::timeout(SEND_TIMEOUT, write).await {
        Ok(Ok(())) => Ok(()),
        Ok(Err(e)) => Err(format!("cannot send: {e}")),
        Err(_) => {
            let reason = format!("not reading for {} s", SEND_TIMEOUT.as_secs());
            close(out, CLOSE_POLICY, &reason).await;
            Err(reason)
        }
    }
}

/// Says why the socket closes, best effort: a viewer that is not reading may not get it.
async fn close(out: &mut Out, code: u16, why: &str) {
    // A close frame's reason is at most 123 bytes.
    let mut end = why.len().min(123);
    while !why.is_char_boundary(end) {
        end -= 1;
    }
    let frame = CloseFrame {
        code,
        reason: Utf8Bytes::from(&why[..end]),
    };
    let _ = tokio::time::timeout(
        Duration::from_millis(100),
        out.send(Message::Close(Some(frame))),
    )
    .await;
}

/// 1009 (message too big) for a frame over the limit, else 1002 (protocol error).
fn close_code(error: &axum::Error) -> u16 {
    let text = error.to_string();
    if text.contains("too long") || text.contains("too big") || text.contains("Space limit") {
        CLOSE_TOO_BIG
    } else {
        CLOSE_PROTOCOL
    }
}

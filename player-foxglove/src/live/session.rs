//! One viewer's WebSocket: `serverInfo` and the channels so far, then whatever its outbox
//! gathers, a burst in one write; its requests carried out, a bad one answered with an error
//! `status` and the connection kept. A viewer whose write does not complete within
//! [`player_front::STALLED_AFTER`] (every front's rule, `player_front::socket`) is not
//! reading and is closed; until then it loses its oldest messages, not its connection.

use std::net::SocketAddr;
use std::sync::Arc;

use axum::extract::ws::{Message, WebSocket};
use futures_util::StreamExt;
use player_front::Stopping;
use player_front::socket::{CloseCode, Out, SendError, close, send_within};

use super::hub::{Hub, ViewerId};
use super::outbox::{Batch, Outbox, viewer_outbox};
use super::refusal::Refusal;
use super::wire::{self, Level, Request};

/// Serves one viewer until it or the server goes.
pub async fn serve_viewer(
    socket: WebSocket,
    from: SocketAddr,
    hub: Arc<Hub>,
    session_id: String,
    mut stopping: Stopping,
) {
    let outbox = Arc::new(viewer_outbox());
    outbox.push_control(wire::server_info("player-relay", &session_id));
    let viewer = hub.join(outbox.clone());
    let (mut out, mut incoming) = socket.split();
    let why = loop {
        tokio::select! {
            batch = outbox.next() => {
                let Some(batch) = batch else {
                    close(&mut out, CloseCode::Policy, "the server stops or the viewer lags").await;
                    break "closed by the server".to_string();
                };
                if let Err(why) = send(&mut out, batch).await {
                    break why.to_string();
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
                    close(&mut out, CloseCode::of_error(&e), &why).await;
                    break why;
                }
            },
            // The server stopped; on a handed runtime nothing else would end this task.
            _ = stopping.wait() => {
                close(&mut out, CloseCode::GoingAway, "the server stops").await;
                break "the server stops".to_string();
            }
        }
    };
    hub.leave(viewer);
    tracing::debug!(viewer, %from, "Foxglove viewer gone: {why}");
}

/// Carries out one text request; what is wrong with it goes back as an error status.
fn request(hub: &Hub, outbox: &Outbox, viewer: ViewerId, text: &str) {
    let mut refusals = Vec::new();
    match wire::parse_request(text) {
        Err(refusal) => refusals.push(refusal),
        Ok(Request::Subscribe(subscriptions)) => {
            for (subscription, channel) in subscriptions {
                refusals.extend(hub.subscribe(viewer, subscription, channel).err());
            }
        }
        Ok(Request::Unsubscribe(subscriptions)) => {
            for subscription in subscriptions {
                refusals.extend(hub.unsubscribe(viewer, subscription).err());
            }
        }
    }
    if !refusals.is_empty() {
        let why: Vec<String> = refusals.iter().map(Refusal::to_string).collect();
        outbox.push_control(wire::status(Level::Error, &why.join("; ")));
    }
}

/// Writes a batch and flushes it once, all within [`player_front::STALLED_AFTER`].
async fn send(out: &mut Out, batch: Batch) -> Result<(), SendError> {
    if batch.dropped > 0 {
        tracing::debug!(dropped = batch.dropped, "a Foxglove viewer fell behind");
    }
    let control = batch.control.into_iter().map(Message::Text);
    let data = batch.data.into_iter().map(|data| {
        let frame = wire::message_data(data.subscription, data.log_time, &data.payload);
        Message::Binary(frame)
    });
    send_within(out, control.chain(data)).await
}

//! Foxglove clients for a [`Crowd`]: each speaks the Foxglove WebSocket protocol to the
//! relay's Foxglove server (`player-relay --foxglove`), as Foxglove Studio or Lichtblick would:
//! it subscribes to every scan and pose channel as it is advertised, and takes the latency of
//! each message from its log time (the Player timestamp) to its arrival here.

use std::collections::HashSet;
use std::time::Duration;

use futures_util::{SinkExt, StreamExt};
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::tungstenite::client::IntoClientRequest;
use tokio_tungstenite::tungstenite::http::HeaderValue;

use crate::BenchError;
use crate::clock::{SharedWindow, unix_seconds};
use crate::crowd::{Crowd, Member, Seen};

/// The subprotocol the Foxglove SDK's server speaks (`foxglove.websocket.v1`, renamed).
const SUBPROTOCOL: &str = "foxglove.sdk.v1";
/// The binary frame of one message: opcode, subscription id, log time, payload.
const MESSAGE_DATA: u8 = 1;

/// Connects `count` Foxglove clients and waits (at most `timeout`) until each has subscribed
/// to the first channels it was advertised.
pub fn connect_foxglove_clients(
    port: u16,
    count: usize,
    window: SharedWindow,
    timeout: Duration,
) -> Result<Crowd, BenchError> {
    Crowd::start("Foxglove clients", count, window, timeout, move |member| {
        client(port, member)
    })
}

async fn client(port: u16, member: Member) -> Seen {
    let Member {
        window,
        mut stop,
        ready,
        ..
    } = member;
    let mut request = format!("ws://127.0.0.1:{port}")
        .into_client_request()
        .map_err(|e| e.to_string())?;
    request.headers_mut().insert(
        "Sec-WebSocket-Protocol",
        HeaderValue::from_static(SUBPROTOCOL),
    );
    let (mut socket, _) = tokio_tungstenite::connect_async(request)
        .await
        .map_err(|e| format!("Foxglove socket on {port}: {e}"))?;
    let mut subscribed = HashSet::new();
    let mut next_subscription = 1u32;
    let mut latencies = Vec::new();
    let mut announced = false;
    loop {
        tokio::select! {
            _ = stop.changed() => return Ok(latencies),
            frame = socket.next() => match frame {
                Some(Ok(Message::Text(text))) => {
                    let wanted = advertised(&text, &mut subscribed);
                    if wanted.is_empty() {
                        continue;
                    }
                    let subscriptions: Vec<serde_json::Value> = wanted
                        .into_iter()
                        .map(|channel| {
                            next_subscription += 1;
                            serde_json::json!({"id": next_subscription, "channelId": channel})
                        })
                        .collect();
                    let subscribe = serde_json::json!({"op": "subscribe", "subscriptions": subscriptions});
                    socket
                        .send(Message::text(subscribe.to_string()))
                        .await
                        .map_err(|e| e.to_string())?;
                    if !announced {
                        announced = true;
                        let _ = ready.send(()).await;
                    }
                }
                Some(Ok(Message::Binary(data))) => {
                    if let Some(sent) = log_time(&data)
                        && window.contains(sent)
                    {
                        latencies.push(unix_seconds() - sent);
                    }
                }
                Some(Ok(_)) => {}
                Some(Err(e)) => return Err(format!("Foxglove socket: {e}")),
                None => return Err("the relay closed a Foxglove socket".into()),
            },
        }
    }
}

/// The scan and pose channels an `advertise` message names that are new.
fn advertised(text: &str, subscribed: &mut HashSet<u64>) -> Vec<u64> {
    let Ok(message) = serde_json::from_str::<serde_json::Value>(text) else {
        return Vec::new();
    };
    if message["op"] != "advertise" {
        return Vec::new();
    }
    let Some(channels) = message["channels"].as_array() else {
        return Vec::new();
    };
    channels
        .iter()
        .filter(|c| {
            c["topic"]
                .as_str()
                .is_some_and(|t| t.ends_with("/scan") || t.ends_with("/pose"))
        })
        .filter_map(|c| c["id"].as_u64())
        .filter(|id| subscribed.insert(*id))
        .collect()
}

/// A message's log time in Unix seconds.
fn log_time(data: &[u8]) -> Option<f64> {
    if data.len() < 13 || data[0] != MESSAGE_DATA {
        return None;
    }
    let nanos = u64::from_le_bytes(data[5..13].try_into().ok()?);
    Some(nanos as f64 * 1e-9)
}

//! The Foxglove WebSocket protocol's messages as they travel (the public spec,
//! github.com/foxglove/ws-protocol docs/spec.md): the JSON text messages the server sends
//! (`serverInfo`, `advertise`, `status`), the client's JSON requests (`subscribe`,
//! `unsubscribe`), and the binary `Message Data` frame.

use axum::extract::ws::Utf8Bytes;
use bytes::{BufMut, Bytes, BytesMut};
use serde::Deserialize;
use serde_json::json;

pub use super::ids::{ChannelId, SubscriptionId};
use super::refusal::Refusal;

/// The subprotocols a viewer may offer, in the server's order of preference: the spec's name
/// (Lichtblick, older Foxglove Studio) and the SDK's name for the same protocol (newer
/// Foxglove clients).
pub const SUBPROTOCOLS: [&str; 2] = ["foxglove.websocket.v1", "foxglove.sdk.v1"];

/// The server-to-client binary opcode of one message on a subscription.
pub const MESSAGE_DATA: u8 = 0x01;

/// Opcode, subscription id (u32 LE), log time in ns (u64 LE).
pub const MESSAGE_HEADER_LEN: usize = 1 + 4 + 8;

/// A `status` message's level.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Level {
    Warning = 1,
    Error = 2,
}

/// The first message a viewer gets. No capabilities: the viewer only subscribes (no client
/// publishing, parameters, services or time), so there is no encoding it may publish in.
pub fn server_info(name: &str, session_id: &str) -> Utf8Bytes {
    text(&json!({
        "op": "serverInfo",
        "name": name,
        "capabilities": [],
        "supportedEncodings": [],
        "metadata": {},
        "sessionId": session_id,
    }))
}

/// One channel as `advertise` lists it: the schema is the FileDescriptorSet, base64.
pub fn channel(id: ChannelId, topic: &str, schema: &foxglove::Schema, encoding: &str) -> String {
    use base64::Engine;
    json!({
        "id": id,
        "topic": topic,
        "encoding": encoding,
        "schemaName": schema.name,
        "schema": base64::engine::general_purpose::STANDARD.encode(&schema.data),
        "schemaEncoding": schema.encoding,
    })
    .to_string()
}

/// An `advertise` of channels already written by [`channel`].
pub fn advertise<'a>(channels: impl IntoIterator<Item = &'a str>) -> Utf8Bytes {
    let mut out = String::from(r#"{"op":"advertise","channels":["#);
    for (i, channel) in channels.into_iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        out.push_str(channel);
    }
    out.push_str("]}");
    Utf8Bytes::from(out)
}

pub fn status(level: Level, message: &str) -> Utf8Bytes {
    text(&json!({ "op": "status", "level": level as u8, "message": message }))
}

fn text(value: &serde_json::Value) -> Utf8Bytes {
    Utf8Bytes::from(value.to_string())
}

/// A `Message Data` frame: the header, then the payload (encoded once, shared by every
/// viewer; only these 13 bytes differ between them).
pub fn message_data(subscription: SubscriptionId, log_time: u64, payload: &[u8]) -> Bytes {
    let mut out = BytesMut::with_capacity(MESSAGE_HEADER_LEN + payload.len());
    out.put_u8(MESSAGE_DATA);
    out.put_u32_le(subscription);
    out.put_u64_le(log_time);
    out.put_slice(payload);
    out.freeze()
}

/// What a viewer asks, of the requests this server serves.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Request {
    Subscribe(Vec<(SubscriptionId, ChannelId)>),
    Unsubscribe(Vec<SubscriptionId>),
}

#[derive(Deserialize)]
#[serde(tag = "op", rename_all = "camelCase")]
enum Incoming {
    Subscribe {
        subscriptions: Vec<Subscription>,
    },
    Unsubscribe {
        #[serde(rename = "subscriptionIds")]
        subscription_ids: Vec<SubscriptionId>,
    },
}

#[derive(Deserialize)]
struct Subscription {
    id: SubscriptionId,
    #[serde(rename = "channelId")]
    channel_id: ChannelId,
}

/// Operations of the protocol that need a capability this server does not advertise.
const UNSUPPORTED: &[&str] = &[
    "advertise",
    "unadvertise",
    "getParameters",
    "setParameters",
    "subscribeParameterUpdates",
    "unsubscribeParameterUpdates",
    "subscribeConnectionGraph",
    "unsubscribeConnectionGraph",
    "fetchAsset",
];

/// A client's text message as a request, or why not.
pub fn parse_request(text: &str) -> Result<Request, Refusal> {
    match serde_json::from_str::<Incoming>(text) {
        Ok(Incoming::Subscribe { subscriptions }) => Ok(Request::Subscribe(
            subscriptions
                .into_iter()
                .map(|s| (s.id, s.channel_id))
                .collect(),
        )),
        Ok(Incoming::Unsubscribe { subscription_ids }) => {
            Ok(Request::Unsubscribe(subscription_ids))
        }
        Err(e) => {
            let op = serde_json::from_str::<serde_json::Value>(text)
                .ok()
                .and_then(|v| v.get("op").and_then(|op| op.as_str().map(str::to_string)));
            Err(match op {
                Some(op) if UNSUPPORTED.contains(&op.as_str()) => Refusal::Unsupported(op),
                _ => Refusal::Invalid(e.to_string()),
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn requests_parse_and_bad_ones_say_why() {
        assert_eq!(
            parse_request(r#"{"op":"subscribe","subscriptions":[{"id":7,"channelId":3}]}"#),
            Ok(Request::Subscribe(vec![(7, 3)]))
        );
        assert_eq!(
            parse_request(r#"{"op":"unsubscribe","subscriptionIds":[7,8]}"#),
            Ok(Request::Unsubscribe(vec![7, 8]))
        );
        for bad in [
            "nope {",
            r#"{"op":"launchMissiles"}"#,
            r#"{"op":"subscribe"}"#,
        ] {
            let why = parse_request(bad).unwrap_err();
            assert!(matches!(why, Refusal::Invalid(_)), "{bad}: {why}");
        }
        let why = parse_request(r#"{"op":"getParameters","parameterNames":[]}"#).unwrap_err();
        assert_eq!(why, Refusal::Unsupported("getParameters".into()));
        assert!(
            why.to_string().starts_with("Unsupported operation"),
            "{why}"
        );
    }

    #[test]
    fn a_message_frame_is_opcode_subscription_time_payload() {
        let frame = message_data(0x0403_0201, 0x0807_0605_0403_0201, b"xyz");
        assert_eq!(
            &frame[..],
            &[1, 1, 2, 3, 4, 1, 2, 3, 4, 5, 6, 7, 8, b'x', b'y', b'z'][..]
        );
    }

    #[test]
    fn an_advertisement_lists_its_channels() {
        let schema = foxglove::Schema::new("foxglove.Log", "protobuf", b"\x01\x02".to_vec());
        let one = channel(4, "/a", &schema, "protobuf");
        let parsed: serde_json::Value = serde_json::from_str(&advertise([one.as_str()])).unwrap();
        assert_eq!(parsed["op"], "advertise");
        let c = &parsed["channels"][0];
        assert_eq!(c["id"], 4);
        assert_eq!(c["topic"], "/a");
        assert_eq!(c["schemaName"], "foxglove.Log");
        assert_eq!(c["schema"], "AQI=");
        assert_eq!(c["schemaEncoding"], "protobuf");
    }
}

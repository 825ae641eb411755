//! How a recording's records sit in an MCAP file (`docs/RECORDING-FORMAT.md`, "MCAP"): three
//! channels per recorded connection, named and tagged so a reader finds them without parsing
//! topics, and the bytes each message carries.
//!
//! * `/player/<n>/to_client` and `/player/<n>/to_server`: one MCAP message per Player message,
//!   its data exactly the wire bytes (40-byte XDR header, then the body).
//! * `/player/<n>/session`: the connection's life as small JSON objects — `connection` (host
//!   and port), `opened` (the server's 32-byte banner, in hex), `closed` (why).
//!
//! Every MCAP message's log and publish times are the record's time; its sequence number is the
//! record's position in the recording (modulo 2³²). Records are written in the recording's
//! order, which a linear read gives back.

use std::collections::BTreeMap;

use player_proto::capture::Direction;
use player_proto::recording::Event;
use player_proto::wire::{BANNER_LEN, HeaderError};
use serde_json::{Value, json};

/// Why a channel or a message that says it is Player's is not.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum LayoutError {
    #[error("connection number {0:?} is not a number")]
    Connection(String),
    #[error("unknown Player stream {0:?}")]
    UnknownStream(String),
    /// What the JSON reader said.
    #[error("session message is not JSON: {0}")]
    NotJson(String),
    #[error("session message without a string {0:?}")]
    Missing(&'static str),
    #[error("connection event without a port from 0 to 65535")]
    NoPort,
    #[error("unknown session event {0:?}")]
    UnknownEvent(String),
    #[error("banner {0:?} is not {BANNER_LEN} bytes of hex")]
    Banner(String),
    #[error("{0} bytes, no 40-byte Player header")]
    NoHeader(usize),
    #[error("bad Player header: {0}")]
    Header(#[from] HeaderError),
    #[error("the Player header announces {announced} body bytes, the message holds {holds}")]
    BodySize { announced: u32, holds: usize },
}

/// Channel metadata key: the recorded connection number.
pub const META_CONNECTION: &str = "player.connection";
/// Channel metadata key: which of a connection's streams the channel carries.
pub const META_STREAM: &str = "player.stream";
/// Channel metadata keys: the connection's host and port, when known as the channel starts.
pub const META_HOST: &str = "player.host";
pub const META_PORT: &str = "player.port";

/// The name of the file-level metadata record that marks a file as holding a recording.
pub const FILE_METADATA: &str = "player.recording";

/// Schema of the raw message channels.
pub const MESSAGE_SCHEMA: &str = "player.Message";
pub const MESSAGE_ENCODING: &str = "player-xdr";
const MESSAGE_SCHEMA_TEXT: &str = "A Player 3 message exactly as it crossed the wire: the 40-byte \
XDR header (player_msghdr_t), then `size` bytes of body. See pv3d's docs/RECORDING-FORMAT.md.";

/// Schema of the session channels.
pub const SESSION_SCHEMA: &str = "player.Session";
const SESSION_JSON_SCHEMA: &str = r#"{"type":"object","properties":{"event":{"enum":["connection","opened","closed"]},"host":{"type":"string"},"port":{"type":"integer"},"banner":{"type":"string","description":"the server's 32-byte banner, hex"},"why":{"type":"string"}},"required":["event"]}"#;

/// One of a connection's three channels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Stream {
    ToClient,
    ToServer,
    Session,
}

impl Stream {
    pub const ALL: [Stream; 3] = [Stream::ToClient, Stream::ToServer, Stream::Session];

    pub fn name(self) -> &'static str {
        match self {
            Stream::ToClient => "to_client",
            Stream::ToServer => "to_server",
            Stream::Session => "session",
        }
    }

    pub fn from_name(name: &str) -> Option<Stream> {
        Stream::ALL.into_iter().find(|s| s.name() == name)
    }

    /// The stream a record goes to.
    pub fn of(event: &Event) -> Stream {
        match event {
            Event::Message {
                direction: Direction::ServerToClient,
                ..
            } => Stream::ToClient,
            Event::Message {
                direction: Direction::ClientToServer,
                ..
            } => Stream::ToServer,
            _ => Stream::Session,
        }
    }

    pub fn topic(self, connection: u32) -> String {
        format!("/player/{connection}/{}", self.name())
    }

    /// (schema name, schema encoding, schema data, message encoding).
    pub fn schema(self) -> (&'static str, &'static str, &'static [u8], &'static str) {
        match self {
            Stream::Session => (
                SESSION_SCHEMA,
                "jsonschema",
                SESSION_JSON_SCHEMA.as_bytes(),
                "json",
            ),
            _ => (
                MESSAGE_SCHEMA,
                MESSAGE_ENCODING,
                MESSAGE_SCHEMA_TEXT.as_bytes(),
                MESSAGE_ENCODING,
            ),
        }
    }

    /// The channel metadata of this stream of a connection.
    pub fn metadata(self, connection: u32, known: Option<(&str, u16)>) -> BTreeMap<String, String> {
        let mut meta = BTreeMap::from([
            (META_CONNECTION.to_string(), connection.to_string()),
            (META_STREAM.to_string(), self.name().to_string()),
        ]);
        if let Some((host, port)) = known {
            meta.insert(META_HOST.into(), host.into());
            meta.insert(META_PORT.into(), port.to_string());
        }
        meta
    }
}

/// A channel's connection and stream from its metadata; `None` if it is not a Player channel.
pub fn player_channel(
    metadata: &BTreeMap<String, String>,
) -> Option<Result<(u32, Stream), LayoutError>> {
    let connection = metadata.get(META_CONNECTION)?;
    let stream = metadata.get(META_STREAM)?;
    Some(
        match (connection.parse::<u32>(), Stream::from_name(stream)) {
            (Ok(c), Some(s)) => Ok((c, s)),
            (Err(_), _) => Err(LayoutError::Connection(connection.clone())),
            (_, None) => Err(LayoutError::UnknownStream(stream.clone())),
        },
    )
}

/// A session record's JSON. `None` for a message (whose data is its wire bytes).
pub fn session_json(event: &Event) -> Option<Vec<u8>> {
    let value = match event {
        Event::Connection { host, port } => {
            json!({"event": "connection", "host": host, "port": port})
        }
        Event::Opened { banner } => json!({"event": "opened", "banner": hex(banner)}),
        Event::Closed { why } => json!({"event": "closed", "why": why}),
        Event::Message { .. } => return None,
    };
    Some(value.to_string().into_bytes())
}

/// Parses a session message back into its event.
pub fn parse_session(data: &[u8]) -> Result<Event, LayoutError> {
    let value: Value =
        serde_json::from_slice(data).map_err(|e| LayoutError::NotJson(e.to_string()))?;
    let text = |key: &'static str| {
        value
            .get(key)
            .and_then(Value::as_str)
            .ok_or(LayoutError::Missing(key))
    };
    match text("event")? {
        "connection" => {
            let port = value
                .get("port")
                .and_then(Value::as_u64)
                .and_then(|p| u16::try_from(p).ok())
                .ok_or(LayoutError::NoPort)?;
            Ok(Event::Connection {
                host: text("host")?.to_string(),
                port,
            })
        }
        "opened" => Ok(Event::Opened {
            banner: unhex(text("banner")?)?,
        }),
        "closed" => Ok(Event::Closed {
            why: text("why")?.to_string(),
        }),
        other => Err(LayoutError::UnknownEvent(other.to_string())),
    }
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

fn unhex(text: &str) -> Result<[u8; BANNER_LEN], LayoutError> {
    let bad = || LayoutError::Banner(text.to_string());
    if text.len() != 2 * BANNER_LEN || !text.is_ascii() {
        return Err(bad());
    }
    let mut banner = [0u8; BANNER_LEN];
    for (i, byte) in banner.iter_mut().enumerate() {
        *byte = u8::from_str_radix(&text[2 * i..2 * i + 2], 16).map_err(|_| bad())?;
    }
    Ok(banner)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn session_events_round_trip() {
        let mut banner = [0u8; BANNER_LEN];
        banner[..14].copy_from_slice(b"Player v.3.0.2");
        banner[31] = 0xff;
        for event in [
            Event::Connection {
                host: "röbot.local".into(),
                port: 6665,
            },
            Event::Opened { banner },
            Event::Closed {
                why: "the server closed the connection".into(),
            },
        ] {
            let json = session_json(&event).expect("a session event");
            assert_eq!(parse_session(&json), Ok(event));
        }
    }

    #[test]
    fn bad_session_messages_say_why() {
        for (data, says) in [
            (&b"\xff"[..], "not JSON"),
            (br#"{"event":"opened","banner":"00"}"#, "not 32 bytes"),
            (br#"{"event":"connection","host":"a","port":70000}"#, "port"),
            (br#"{"event":"dance"}"#, "unknown session event"),
            (br#"{"host":"a"}"#, "\"event\""),
        ] {
            let error = parse_session(data).expect_err("refused").to_string();
            assert!(error.contains(says), "{error}");
        }
    }

    #[test]
    fn channels_are_found_by_metadata() {
        let meta = Stream::ToServer.metadata(7, Some(("localhost", 6665)));
        assert_eq!(player_channel(&meta), Some(Ok((7, Stream::ToServer))));
        assert_eq!(player_channel(&BTreeMap::new()), None);
        let mut bad = meta.clone();
        bad.insert(META_STREAM.into(), "sideways".into());
        assert_eq!(
            player_channel(&bad),
            Some(Err(LayoutError::UnknownStream("sideways".into())))
        );
    }
}

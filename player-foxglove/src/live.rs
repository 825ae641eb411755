//! A live Foxglove WebSocket server (`foxglove.websocket.v1`, the SDK's own server) fed by
//! Player client taps: what Player servers send becomes channels Foxglove Studio and Lichtblick
//! show. `player-relay --foxglove PORT` is its user; anything holding Player clients can be.
//!
//! Every frame from every server goes through one [`Converter`] (it keeps per-robot state:
//! which devices are robots, ranger geometry, map tiles being assembled). Each [`Output`]
//! is logged on a raw channel per topic, made when its first message comes, with the
//! message's schema and the Player timestamp as log time.
//!
//! Some messages come once per connection to a robot: a device's geometry (its transform
//! robot → sensor), the map's grid, a body's shape, a planner's path. A viewer that
//! subscribes later would never see them, so the latest of each (per transform child, or per
//! topic) is kept and sent to that one client when it subscribes (the SDK's
//! `ServerListener::on_subscribe`, called once the subscription is in place). Re-logging
//! them periodically to everyone would also work, but costs every viewer bandwidth forever
//! and leaves a new one waiting up to a period.

use std::collections::HashMap;
use std::net::IpAddr;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{SystemTime, UNIX_EPOCH};

use bytes::Bytes;
use foxglove::messages::log::Level;
use foxglove::websocket::{ChannelView, Client, ServerListener};
use foxglove::{
    ChannelId, Context, FoxgloveError, PartialMetadata, RawChannel, WebSocketServer,
    WebSocketServerHandle,
};
use player_proto::capture::Direction;
use player_proto::client::{ConnectionTap, Tap, TapEvent};
use player_proto::wire::Header;

use crate::frames::timestamp;
use crate::{Converter, FoxgloveMessage, MESSAGE_ENCODING, Output, log};

/// Messages queued per viewer before the oldest are dropped (the SDK's default is 1024).
/// The queue counts messages, not bytes: a viewer that stops reading holds at most this many
/// of them (besides what the kernel buffers), and a camera's raw frame can be a megabyte. 256
/// is about a second of everything a few robots send at 10 Hz, more than a live view needs
/// to ride out a stall, and room for the burst of latched messages a subscription brings.
/// The SDK's control queue (advertisements, status) has the same bound; a viewer that lets
/// it fill is disconnected.
pub const MESSAGE_BACKLOG: usize = 256;

/// Why the live server could not start.
#[derive(Debug, thiserror::Error)]
pub enum LiveError {
    #[error("cannot start the Foxglove WebSocket server on {address}:{port}: {source}")]
    Start {
        address: IpAddr,
        port: u16,
        source: FoxgloveError,
    },
}

/// A running Foxglove WebSocket server; stops when dropped.
pub struct FoxgloveLive {
    hub: Arc<Hub>,
    server: Option<WebSocketServerHandle>,
}

impl FoxgloveLive {
    /// Starts serving on `address:port` (0: any free port, see [`FoxgloveLive::port`]).
    ///
    /// The server runs on the SDK's own tokio runtime, so this must not be called from async
    /// code (the SDK panics there).
    pub fn start(address: IpAddr, port: u16) -> Result<FoxgloveLive, LiveError> {
        let context = Context::new();
        let hub = Arc::new(Hub {
            context: context.clone(),
            state: Mutex::new(State::default()),
        });
        let server = WebSocketServer::new()
            .name("player-relay")
            .context(&context)
            .bind(address.to_string(), port)
            .message_backlog_size(MESSAGE_BACKLOG)
            .listener(Arc::new(Latcher(hub.clone())))
            .start_blocking()
            .map_err(|source| LiveError::Start {
                address,
                port,
                source,
            })?;
        tracing::info!(port = server.port(), "serving Foxglove WebSocket");
        Ok(FoxgloveLive {
            hub,
            server: Some(server),
        })
    }

    /// The port viewers connect to.
    pub fn port(&self) -> u16 {
        self.server.as_ref().map_or(0, WebSocketServerHandle::port)
    }

    /// Viewers connected now.
    pub fn clients(&self) -> usize {
        self.server
            .as_ref()
            .map_or(0, WebSocketServerHandle::client_count)
    }

    /// Topics with a channel so far.
    pub fn topics(&self) -> Vec<String> {
        let mut topics: Vec<String> = self.hub.lock().channels.keys().cloned().collect();
        topics.sort();
        topics
    }

    /// The tap to give each Player client (e.g. `RelayConfig::fronts`): everything the
    /// servers send goes to the viewers.
    pub fn tap(&self) -> Tap {
        let hub = self.hub.clone();
        Arc::new(move |host: &str, port: u16| -> ConnectionTap {
            let hub = hub.clone();
            let robot = format!("{host}:{port}");
            Arc::new(move |time, event| hub.event(&robot, time, event))
        })
    }
}

impl Drop for FoxgloveLive {
    fn drop(&mut self) {
        if let Some(server) = self.server.take() {
            let shutdown = server.stop();
            // Waiting blocks on the SDK's runtime, which async code must not do.
            if tokio::runtime::Handle::try_current().is_ok() {
                shutdown.detach_all();
            } else {
                shutdown.wait_blocking();
            }
        }
    }
}

/// What the taps and the server's listener share.
struct Hub {
    context: Arc<Context>,
    state: Mutex<State>,
}

#[derive(Default)]
struct State {
    converter: Converter,
    channels: HashMap<String, Arc<RawChannel>>,
    /// The newest message of each kind that comes once, by channel and then by what it
    /// describes (a transform's child frame, or the topic itself): encoded, with its log time.
    latched: HashMap<ChannelId, HashMap<String, (Bytes, u64)>>,
}

impl Hub {
    fn lock(&self) -> MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// One tap event of the connection to `robot`, on its robot thread: converting and
    /// queueing for the viewers never waits on them (the SDK drops a slow viewer's oldest).
    fn event(&self, robot: &str, time: SystemTime, event: TapEvent<'_>) {
        let outputs = match event {
            TapEvent::Opened(banner) => vec![log(
                robot,
                system_timestamp(time),
                Level::Info,
                &format!("connected (Player {})", banner.version),
            )],
            TapEvent::Closed(reason) => vec![log(
                robot,
                system_timestamp(time),
                Level::Warning,
                &format!("connection closed: {reason}"),
            )],
            TapEvent::Frame {
                direction: Direction::ServerToClient,
                header,
                body,
            } => return self.frame(robot, header, body),
            TapEvent::Frame { .. } => return,
        };
        let mut state = self.lock();
        for output in outputs {
            let nanos = system_timestamp(time).total_nanos();
            self.publish(&mut state, output, nanos);
        }
    }

    fn frame(&self, robot: &str, header: &Header, body: &Bytes) {
        let mut state = self.lock();
        let outputs = state.converter.server_message(robot, header, body);
        let nanos = timestamp(header.timestamp).total_nanos();
        for output in outputs {
            self.publish(&mut state, output, nanos);
        }
    }

    fn publish(&self, state: &mut State, output: Output, log_time: u64) {
        let channel = match state.channels.get(&output.topic) {
            Some(channel) => channel.clone(),
            None => {
                let built = self
                    .context
                    .channel_builder(output.topic.clone())
                    .schema(output.message.schema())
                    .message_encoding(MESSAGE_ENCODING)
                    .build_raw();
                match built {
                    Ok(channel) => {
                        state.channels.insert(output.topic.clone(), channel.clone());
                        channel
                    }
                    Err(e) => {
                        tracing::warn!(topic = output.topic, "no Foxglove channel: {e}");
                        return;
                    }
                }
            }
        };
        let bytes = Bytes::from(output.message.encode());
        if let Some(key) = latch_key(&output) {
            state
                .latched
                .entry(channel.id())
                .or_default()
                .insert(key, (bytes.clone(), log_time));
        }
        channel.log_with_meta(&bytes, meta(log_time));
    }
}

/// What a message that comes once is kept under, or `None` for one that streams.
fn latch_key(output: &Output) -> Option<String> {
    match &output.message {
        FoxgloveMessage::FrameTransform(t) => Some(t.child_frame_id.clone()),
        FoxgloveMessage::Grid(_) | FoxgloveMessage::SceneUpdate(_) => Some(output.topic.clone()),
        _ => None,
    }
}

fn meta(log_time: u64) -> PartialMetadata {
    PartialMetadata {
        log_time: Some(log_time),
    }
}

fn system_timestamp(time: SystemTime) -> foxglove::messages::Timestamp {
    timestamp(
        time.duration_since(UNIX_EPOCH)
            .map_or(0.0, |d| d.as_secs_f64()),
    )
}

/// Sends a new subscriber what was latched on its channel.
struct Latcher(Arc<Hub>);

impl ServerListener for Latcher {
    fn on_subscribe(&self, client: Client, channel: ChannelView) {
        let state = self.0.lock();
        let (Some(latched), Some(raw)) = (
            state.latched.get(&channel.id()),
            state.channels.get(channel.topic()),
        ) else {
            return;
        };
        for (bytes, log_time) in latched.values() {
            raw.log_with_meta_to_sink(bytes, meta(*log_time), client.sink_id());
        }
    }
}

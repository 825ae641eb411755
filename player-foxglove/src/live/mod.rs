//! A live Foxglove WebSocket server fed by Player client taps: what Player servers send
//! becomes channels Foxglove Studio and Lichtblick show. `player-relay --foxglove PORT` is its
//! user; anything holding Player clients can be.
//!
//! The schemas and the protobuf encoding are the `foxglove` crate's; the transport is this
//! module's own, the server side of the public protocol (github.com/foxglove/ws-protocol,
//! docs/spec.md) that a live viewer needs: both subprotocol names (`foxglove.websocket.v1`,
//! `foxglove.sdk.v1`), `serverInfo`, `advertise`, `subscribe`/`unsubscribe`, `Message Data`,
//! and error `status`es. It replaced the SDK's WebSocket server because of a measurement
//! (BENCHMARKS.md, "Web page and Foxglove clients through one relay"): the SDK writes and
//! flushes one WebSocket message per subscribed message per viewer; here each message is
//! encoded once for all, and a viewer's queued messages leave in one write. The SDK's server
//! also refuses viewers that offer only `foxglove.websocket.v1` (older Lichtblick builds).
//!
//! * [`hub`] — the conversion, the channels and the subscriptions, fed by the taps; a
//!   viewer's subscription is a look at the devices its channel carries, and the relay
//!   subscribes upstream to those alone;
//! * [`channels`] — one channel per topic, and what is latched on it for later subscribers;
//! * [`outbox`] — a viewer's bounded queue (oldest dropped, in count and bytes): the kit's
//!   (`player_front::outbox`) with Foxglove's bounds;
//! * [`session`] — a viewer's socket: bursts out, requests in;
//! * [`refusal`] — why a request is refused, as the error status says it;
//! * [`server`] — the listener and the upgrade, on the server's runtime: its own, or one it
//!   was handed ([`FoxgloveLive::start_on`]);
//! * [`wire`] — the protocol's messages.

mod channels;
mod hub;
pub mod ids;
pub mod outbox;
pub mod refusal;
pub mod server;
pub mod session;
pub mod wire;

use std::net::{IpAddr, SocketAddr};
use std::sync::Arc;
use std::time::{SystemTime, UNIX_EPOCH};

use tokio::runtime::Handle;

use player_front::{Front, FrontRuntime, Watch, Watching};
use player_proto::RobotId;
use player_proto::client::{ConnectionTap, RobotTap, Tap, unnamed};

use hub::Hub;
pub use outbox::{BACKLOG_BYTES, MESSAGE_BACKLOG};

/// Why the live server could not start.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum LiveError {
    #[error("cannot start the Foxglove WebSocket server on {address}:{port}: {source}")]
    Start {
        address: IpAddr,
        port: u16,
        source: std::io::Error,
    },
}

/// A running Foxglove WebSocket server, on its own runtime or a handed one; stops when
/// dropped.
pub struct FoxgloveLive {
    hub: Arc<Hub>,
    port: u16,
    runtime: FrontRuntime,
}

impl FoxgloveLive {
    /// Starts serving on `address:port` (0: any free port, see [`FoxgloveLive::port`]), on a
    /// runtime of its own.
    pub fn start(address: IpAddr, port: u16) -> Result<FoxgloveLive, LiveError> {
        let runtime = FrontRuntime::own("foxglove-ws", 2).map_err(|source| LiveError::Start {
            address,
            port,
            source,
        })?;
        FoxgloveLive::serve(runtime, address, port)
    }

    /// As [`FoxgloveLive::start`], on the runtime of `handle` (the relay's for all its fronts,
    /// or an embedding program's): dropping the server closes its viewers and its listener and
    /// leaves that runtime running.
    pub fn start_on(handle: Handle, address: IpAddr, port: u16) -> Result<FoxgloveLive, LiveError> {
        FoxgloveLive::serve(FrontRuntime::on(handle), address, port)
    }

    fn serve(runtime: FrontRuntime, address: IpAddr, port: u16) -> Result<FoxgloveLive, LiveError> {
        let error = |source| LiveError::Start {
            address,
            port,
            source,
        };
        let listener = server::listen(SocketAddr::new(address, port))
            .and_then(|std| {
                let _entered = runtime.handle().enter();
                tokio::net::TcpListener::from_std(std)
            })
            .map_err(error)?;
        let port = listener.local_addr().map_err(error)?.port();
        let hub = Arc::new(Hub::default());
        let session_id = SystemTime::now()
            .duration_since(UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos())
            .to_string();
        runtime.spawn(server::serve(
            listener,
            hub.clone(),
            session_id,
            runtime.stopping(),
        ));
        tracing::info!(port, "serving Foxglove WebSocket");
        Ok(FoxgloveLive { hub, port, runtime })
    }

    /// Tasks of the server running now (its listener; viewers are not counted).
    pub fn tasks(&self) -> usize {
        self.runtime.tasks()
    }

    /// The port viewers connect to.
    pub fn port(&self) -> u16 {
        self.port
    }

    /// Viewers connected now.
    pub fn clients(&self) -> usize {
        self.hub.viewers()
    }

    /// Devices the viewers look at now (through their subscriptions), over every robot.
    pub fn looks(&self) -> usize {
        self.hub.looks()
    }

    /// Topics with a channel so far.
    pub fn topics(&self) -> Vec<String> {
        self.hub.topics()
    }

    /// The tap to give the relay (`RelayConfig::fronts`): everything the robots' servers
    /// send goes to the viewers, under topics `/<robot>/…` named as [`RobotId`] says it (its
    /// name, else `host:port`).
    pub fn robot_tap(&self) -> RobotTap {
        let hub = self.hub.clone();
        Arc::new(move |robot: &RobotId| -> ConnectionTap {
            let hub = hub.clone();
            let robot = robot.to_string();
            // The robot's own conversion state, used on its thread alone.
            let converter = std::sync::Mutex::new(crate::Converter::new());
            Arc::new(move |time, event| hub.event(&robot, &converter, time, event))
        })
    }

    /// The tap to give Player clients that know no names: topics `/<host:port>/…`.
    pub fn tap(&self) -> Tap {
        unnamed(self.robot_tap())
    }
}

/// Foxglove as one of the relay's fronts: each robot's topics under its name.
impl Front for FoxgloveLive {
    fn name(&self) -> &str {
        "Foxglove"
    }

    fn arrived(&self, robot: &RobotId) -> ConnectionTap {
        (self.robot_tap())(robot)
    }

    fn watch(&self, robot: &RobotId, watch: Watch) -> Watching {
        self.hub.watch(&robot.to_string(), watch);
        Watching::AsLooked
    }

    /// Viewers closed, the listener closed; the runtime, if handed, runs on.
    fn stop(&self) {
        self.hub.close_all();
        self.runtime.stop();
    }
}

impl Drop for FoxgloveLive {
    /// The viewers are told before the runtime (dropped next) stops their sessions.
    fn drop(&mut self) {
        self.hub.close_all();
    }
}

//! The Player client: one thread per robot connection (the design the ERF paper found to
//! scale where a single polling thread did not).
//!
//! The thread owns the socket, decodes, keeps the newest data of each subscribed device with
//! receive time, server timestamp and a sequence number, calls a notifier when something new
//! arrived, and reconnects with backoff — restoring the data mode, the replace rule and the
//! subscriptions — when the server goes away. The [`Client`] handle is synchronous: blocking
//! calls with timeouts, and non-blocking reads of the newest data, usable from a UI thread.
//!
//! ```no_run
//! use player_proto::client::{Client, ClientOptions};
//! let robot = Client::connect("localhost", 6665, ClientOptions::default()).unwrap();
//! for device in robot.devices() {
//!     println!("{} driven by {}", device.addr, device.driver);
//! }
//! let base = robot.position2d(0);
//! base.subscribe().unwrap();
//! base.set_velocity(0.3, 0.0, 0.1);
//! ```

mod liveness;
mod multi;
mod options;
mod proxies;
mod replace_rule;
mod requests;
mod responder;
mod robot_thread;
mod shared;
mod typed;

use std::sync::Arc;
use std::sync::mpsc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use tokio::sync::mpsc::{UnboundedSender, unbounded_channel};

pub use multi::MultiClient;
pub use options::{Backoff, ClientOptions, DataMode, Notifier};
pub use proxies::{
    CameraProxy, FiducialProxy, LaserProxy, Position2dProxy, RangerProxy, SonarProxy,
};
pub use replace_rule::{ReplaceAction, ReplaceRule};
pub use requests::RequestError;
pub use responder::Responder;
pub use shared::{ConnectionState, DeviceInfo, DeviceStats, Stamped};

use crate::interfaces::player::{self, DataModeReq, DeviceReq, Player};
use crate::message::{Body, Message};
use crate::wire::{Banner, DevAddr, Interface, MsgType, PlayerString};
use robot_thread::Command;
use shared::Shared;

/// Why a client could not connect.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ConnectError {
    #[error("cannot reach the Player server at {host}:{port}: {why}")]
    Unreachable {
        host: String,
        port: u16,
        why: String,
    },
    #[error("cannot start the robot thread: {0}")]
    Thread(String),
}

/// A reply that is on its way; poll it from a UI thread, never blocking.
pub struct PendingReply(mpsc::Receiver<Result<Message, RequestError>>);

impl PendingReply {
    /// The outcome if it has arrived.
    pub fn try_get(&self) -> Option<Result<Message, RequestError>> {
        match self.0.try_recv() {
            Ok(outcome) => Some(outcome),
            Err(mpsc::TryRecvError::Empty) => None,
            Err(mpsc::TryRecvError::Disconnected) => Some(Err(RequestError::Disconnected(
                "the robot thread ended".into(),
            ))),
        }
    }

    /// Waits for the outcome, at most `timeout`.
    pub fn wait(self, timeout: Duration) -> Result<Message, RequestError> {
        match self.0.recv_timeout(timeout) {
            Ok(outcome) => outcome,
            Err(mpsc::RecvTimeoutError::Timeout) => Err(RequestError::Timeout(timeout)),
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                Err(RequestError::Disconnected("the robot thread ended".into()))
            }
        }
    }
}

/// A connection to one Player server (one robot, one port).
pub struct Client {
    host: String,
    port: u16,
    options: ClientOptions,
    shared: Arc<Shared>,
    commands: UnboundedSender<Command>,
    thread: Option<JoinHandle<()>>,
}

impl Client {
    /// Starts the robot thread and returns at once; the thread keeps trying to connect (see
    /// [`Client::state`]). Use this when an unreachable robot must not hold anything up.
    pub fn spawn(host: &str, port: u16, options: ClientOptions) -> Result<Client, ConnectError> {
        let shared = Arc::new(Shared::new(options.data_mode, options.replace_old_data));
        let (commands, receiver) = unbounded_channel();
        let thread = {
            let (host, options, shared) = (host.to_string(), options.clone(), shared.clone());
            std::thread::Builder::new()
                .name(format!("player {host}:{port}"))
                .spawn(move || robot_thread::run(host, port, options, shared, receiver))
                .map_err(|e| ConnectError::Thread(e.to_string()))?
        };
        Ok(Client {
            host: host.to_string(),
            port,
            options,
            shared,
            commands,
            thread: Some(thread),
        })
    }

    /// Connects and waits until the handshake is done (device list and driver names known).
    /// Fails if the server cannot be reached within the connect and request timeouts.
    pub fn connect(host: &str, port: u16, options: ClientOptions) -> Result<Client, ConnectError> {
        let limit = options.connect_timeout + options.request_timeout;
        let client = Client::spawn(host, port, options)?;
        let deadline = Instant::now() + limit;
        loop {
            match client.state() {
                ConnectionState::Connected => return Ok(client),
                ConnectionState::Failed(why) => {
                    return Err(ConnectError::Unreachable {
                        host: host.into(),
                        port,
                        why,
                    });
                }
                ConnectionState::Reconnecting { .. } => {
                    return Err(ConnectError::Unreachable {
                        host: host.into(),
                        port,
                        why: "connection refused or lost during the handshake".into(),
                    });
                }
                ConnectionState::Connecting if Instant::now() >= deadline => {
                    return Err(ConnectError::Unreachable {
                        host: host.into(),
                        port,
                        why: format!("no handshake within {limit:?}"),
                    });
                }
                ConnectionState::Connecting => std::thread::sleep(Duration::from_millis(5)),
            }
        }
    }

    pub fn host(&self) -> &str {
        &self.host
    }

    pub fn port(&self) -> u16 {
        self.port
    }

    pub fn state(&self) -> ConnectionState {
        self.shared.state()
    }

    pub fn banner(&self) -> Option<Banner> {
        self.shared.banner.lock().expect("banner").clone()
    }

    /// The devices the server reported, with driver names (from the last handshake).
    pub fn devices(&self) -> Vec<DeviceInfo> {
        self.shared.devices.lock().expect("devices").clone()
    }

    /// Why the last connection ended (the server closed it, stalled, sent garbage …), if one
    /// has ended.
    pub fn last_disconnect(&self) -> Option<String> {
        self.shared
            .last_disconnect
            .lock()
            .expect("last disconnect")
            .clone()
    }

    /// The data mode in force (or to be restored on the next connection).
    pub fn data_mode(&self) -> DataMode {
        *self.shared.data_mode.lock().expect("data mode")
    }

    /// Switches between PUSH and PULL at run time. The mode is remembered before the request
    /// goes out, so it is restored after a reconnect even if this request fails because the
    /// server is away at the moment.
    pub fn set_data_mode(&self, mode: DataMode) -> Result<(), RequestError> {
        *self.shared.data_mode.lock().expect("data mode") = mode;
        let body = DataModeReq {
            mode: match mode {
                DataMode::Push => player::DATAMODE_PUSH,
                DataMode::Pull => player::DATAMODE_PULL,
            },
        };
        self.request(
            DevAddr::local(Interface::PLAYER, 0),
            player::REQ_DATAMODE,
            Body::Player(Player::DataMode(body)),
        )
        .map(|_| ())
    }

    /// The replace rules in force, in the order the server tries them.
    pub fn replace_rules(&self) -> Vec<ReplaceRule> {
        self.shared
            .replace_rules
            .lock()
            .expect("replace rules")
            .clone()
    }

    /// Adds a replace rule to this connection's queue on the server. Remembered like the data
    /// mode and replayed in order after a reconnect.
    ///
    /// The server tries rules in the order they were added and the first match decides, so a
    /// narrow rule added after a broader one that matches the same messages (such as the
    /// default of [`ClientOptions::replace_old_data`]) has no effect; re-adding a rule with
    /// the same filters changes its action instead.
    pub fn add_replace_rule(&self, rule: ReplaceRule) -> Result<(), RequestError> {
        replace_rule::remember(
            &mut self.shared.replace_rules.lock().expect("replace rules"),
            rule,
        );
        self.request(
            DevAddr::local(Interface::PLAYER, 0),
            player::REQ_ADD_REPLACE_RULE,
            Body::Player(Player::AddReplaceRule(rule.to_request())),
        )
        .map(|_| ())
    }

    /// Messages from the server that could not be used (undecodable, replies to nothing).
    pub fn rejected(&self) -> u64 {
        *self.shared.rejected.lock().expect("rejected")
    }

    /// A device address on this server (host and port as libplayerc sends them).
    pub fn addr(&self, interf: Interface, index: u16) -> DevAddr {
        DevAddr {
            host: 0,
            robot: u32::from(self.port),
            interf,
            index,
        }
    }

    /// Sends a request; the reply arrives later.
    pub fn request_async(&self, addr: DevAddr, subtype: u8, body: Body) -> PendingReply {
        let (reply, receiver) = mpsc::channel();
        let message = Message::new(
            self.addr(addr.interf, addr.index),
            MsgType::Req,
            subtype,
            body,
        );
        let command = Command::Request {
            message,
            timeout: self.options.request_timeout,
            reply,
        };
        if let Err(tokio::sync::mpsc::error::SendError(Command::Request { reply, .. })) =
            self.commands.send(command)
        {
            let _ = reply.send(Err(RequestError::Disconnected(
                "the robot thread ended".into(),
            )));
        }
        PendingReply(receiver)
    }

    /// Sends a request and waits for its ACK (a NACK or the timeout is an error).
    pub fn request(&self, addr: DevAddr, subtype: u8, body: Body) -> Result<Message, RequestError> {
        // The thread enforces the timeout; the margin only guards against a stuck thread.
        self.request_async(addr, subtype, body)
            .wait(self.options.request_timeout + Duration::from_secs(1))
    }

    /// Sends a command (fire and forget). The subtype follows from the typed body.
    pub fn command(&self, addr: DevAddr, body: impl Into<Body>) {
        let body = body.into();
        let Some((_, subtype)) = body.kind() else {
            tracing::warn!("a command needs a typed body");
            return;
        };
        let message = Message::new(
            self.addr(addr.interf, addr.index),
            MsgType::Cmd,
            subtype,
            body,
        );
        let _ = self.commands.send(Command::Send(message));
    }

    /// Subscribes to a device; returns its driver name. The subscription is restored after a
    /// reconnect. An ACK that carries an error access is an error.
    pub fn subscribe(&self, addr: DevAddr) -> Result<String, RequestError> {
        let key = (addr.interf, addr.index);
        self.shared
            .subscriptions
            .lock()
            .expect("subscriptions")
            .insert(key);
        match self.device_request(addr, player::OPEN_MODE) {
            Ok(driver) => Ok(driver),
            Err(e) => {
                self.shared
                    .subscriptions
                    .lock()
                    .expect("subscriptions")
                    .remove(&key);
                Err(e)
            }
        }
    }

    /// Subscribes without waiting: data is kept from now on and the reply arrives later (check
    /// its access). For a UI that must not block on a slow server.
    pub fn subscribe_async(&self, addr: DevAddr) -> PendingReply {
        self.shared
            .subscriptions
            .lock()
            .expect("subscriptions")
            .insert((addr.interf, addr.index));
        let req = DeviceReq {
            addr: DevAddr::local(addr.interf, addr.index),
            access: player::OPEN_MODE,
            driver_name: PlayerString::default(),
        };
        self.request_async(
            DevAddr::local(Interface::PLAYER, 0),
            player::REQ_DEV,
            Body::Player(Player::Device(req)),
        )
    }

    /// Unsubscribes and forgets the device's data.
    pub fn unsubscribe(&self, addr: DevAddr) -> Result<(), RequestError> {
        self.shared
            .subscriptions
            .lock()
            .expect("subscriptions")
            .remove(&(addr.interf, addr.index));
        self.shared.forget(addr.interf, addr.index);
        self.device_request(addr, player::CLOSE_MODE).map(|_| ())
    }

    fn device_request(&self, addr: DevAddr, access: u8) -> Result<String, RequestError> {
        let req = DeviceReq {
            addr: DevAddr::local(addr.interf, addr.index),
            access,
            driver_name: PlayerString::default(),
        };
        let reply = self.request(
            DevAddr::local(Interface::PLAYER, 0),
            player::REQ_DEV,
            Body::Player(Player::Device(req)),
        )?;
        match reply.body {
            Body::Player(Player::Device(d)) if d.access == access => {
                Ok(d.driver_name.as_str().into_owned())
            }
            Body::Player(Player::Device(d)) => Err(RequestError::AccessDenied(d.access)),
            _ => Err(RequestError::AccessDenied(player::ERROR_MODE)),
        }
    }

    /// The newest DATA message of `subtype` from a subscribed device.
    pub fn latest(&self, addr: DevAddr, subtype: u8) -> Option<Stamped> {
        self.shared
            .latest
            .lock()
            .expect("latest")
            .get(&(addr.interf, addr.index, subtype))
            .cloned()
    }

    /// Messages and bytes received from a device so far.
    pub fn stats(&self, addr: DevAddr) -> DeviceStats {
        self.shared
            .stats
            .lock()
            .expect("stats")
            .get(&(addr.interf, addr.index))
            .copied()
            .unwrap_or_default()
    }

    /// PULL mode: asks for a round of data and waits for its SYNCH; returns how many DATA
    /// messages the round brought (stored as usual). A round with no data has no SYNCH, so
    /// this times out if no subscribed device publishes.
    pub fn pull(&self) -> Result<usize, RequestError> {
        let (waiter, receiver) = mpsc::channel();
        let _ = self.commands.send(Command::Pull(waiter));
        let timeout = self.options.request_timeout;
        match receiver.recv_timeout(timeout) {
            Ok(outcome) => outcome,
            Err(mpsc::RecvTimeoutError::Timeout) => Err(RequestError::Timeout(timeout)),
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                Err(RequestError::Disconnected("the robot thread ended".into()))
            }
        }
    }

    /// Closes the connection and ends the thread.
    pub fn close(&mut self) {
        let _ = self.commands.send(Command::Shutdown);
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

impl Drop for Client {
    fn drop(&mut self) {
        self.close();
    }
}

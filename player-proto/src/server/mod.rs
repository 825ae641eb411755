//! The server side of the Player protocol: accept clients on one or several ports (a port is a
//! robot), send the banner, answer the `player` interface the way a Player 3 server does
//! (device list, driver names, subscriptions, PUSH/PULL, data requests, replace rules), route
//! commands and requests to [`Device`]s, and push each device's data to its subscribers.
//!
//! A mock laser in a few lines:
//!
//! ```no_run
//! use player_proto::server::{Device, Reply, Server, ServerConfig};
//! use player_proto::interfaces::laser::{Laser, LaserScan};
//! use player_proto::message::{Body, Message};
//!
//! struct MockLaser;
//! impl Device for MockLaser {
//!     fn driver_name(&self) -> &str { "sicklms200" }
//!     fn on_request(&mut self, _request: &Message) -> Reply { Reply::Nack }
//! }
//!
//! let mut config = ServerConfig::default();
//! let robot = config.robot(0); // port 0: any free port
//! config.device(robot, "laser:0".parse().unwrap(), MockLaser);
//! let server = Server::start(config).unwrap();
//! let mut addr: player_proto::DevAddr = "laser:0".parse().unwrap();
//! addr.robot = u32::from(server.port(robot));
//! let scan = LaserScan { ranges: vec![1.0; 181], ..LaserScan::default() };
//! server.publisher().publish(addr, 1, Body::Laser(Laser::Scan(scan)), 0.0);
//! ```
//!
//! Locks, and the one order they are taken in (a cycle would deadlock a session's thread
//! against a device's own): a session's thread holds a **device** while its hooks run
//! (`on_request`, `on_subscribe` …); a hook may take the device's own locks (a simulation's)
//! and may publish; a session subscribing takes its own **subscriptions** and, released
//! first, the device's **subscriber list**; publishing takes a device's subscriber list, then
//! each subscriber's **queue**. So: device → the device's own locks → subscriptions, or
//! subscriber list → queue, never backwards — a device's
//! thread (a simulation's step) may publish while holding its own locks, because nothing the
//! server holds while taking a device's lock is taken by publishing.
//!

mod control;
mod device;
mod direct;
mod lockstep;
mod publisher;
mod queue;
mod session;
mod state;

use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::sync::atomic::AtomicU64;
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

pub use crate::delivery::{DataMode, ReplaceAction, ReplaceRule};
pub use control::{CommandGate, Commanders, Peer};
pub use device::{Device, Reply};
pub use lockstep::{Lockstep, StepCause};
pub use publisher::{DeviceKey, Publisher};
pub use queue::{OutQueue, QUEUE_LIMIT};
use state::{DeviceSlot, ServerState};

use crate::wire::{Banner, DEFAULT_MAX_BODY, DevAddr};

/// What to serve.
pub struct ServerConfig {
    /// Address to listen on; 127.0.0.1 by default.
    pub bind: IpAddr,
    /// The version in the banner.
    pub version: String,
    /// Largest message body accepted from a client.
    pub max_body: usize,
    /// Who may command devices; everyone, as in Player, by default.
    pub commanders: Commanders,
    /// Replace rules every connection's queue starts with (a client adds its own after
    /// them). `ReplaceRule::newest_data()` here gives a slow client fresh data rather than a
    /// backlog without its asking.
    pub queue_rules: Vec<ReplaceRule>,
    /// The kernel send buffer of each connection, bytes (`None`: the system's, which on
    /// loopback grows to megabytes). Small, it bounds how much stale data a slow client can
    /// have waiting in the kernel while newer data replaces the older in its queue.
    pub send_buffer: Option<usize>,
    /// Whoever publishes writes each connection's share itself, in one non-blocking write
    /// (`server/direct.rs`), instead of waking the connection's writer task: no thread
    /// wake-up per connection per publish. For one thread publishing to many connections a
    /// little each (a simulation's step); off by default, where one message fans out to many
    /// connections from a thread that has other work (a relay's upstream).
    pub publisher_writes: bool,
    /// Name of the server's threads, to tell its CPU time from others' in one process.
    pub thread_name: String,
    /// A lockstep simulation's turnstile: every admitted command is reported to it, and a
    /// driver's second command in one step waits for the step ([`Lockstep`]).
    pub lockstep: Option<Arc<Lockstep>>,
    ports: Vec<u16>,
    devices: Vec<(usize, DevAddr, Box<dyn Device>)>,
}

impl Default for ServerConfig {
    fn default() -> Self {
        ServerConfig {
            bind: IpAddr::V4(Ipv4Addr::LOCALHOST),
            version: "3.1.1-dev".into(),
            max_body: DEFAULT_MAX_BODY,
            commanders: Commanders::Everyone,
            queue_rules: Vec::new(),
            send_buffer: None,
            publisher_writes: false,
            thread_name: "player-server".into(),
            lockstep: None,
            ports: Vec::new(),
            devices: Vec::new(),
        }
    }
}

impl ServerConfig {
    /// Adds a robot served on `port` (0 = any free port) and returns its number.
    pub fn robot(&mut self, port: u16) -> usize {
        self.ports.push(port);
        self.ports.len() - 1
    }

    /// Adds a device to a robot; only the interface and index of `addr` are used.
    pub fn device(&mut self, robot: usize, addr: DevAddr, device: impl Device) {
        self.devices.push((robot, addr, Box::new(device)));
    }
}

/// Why the server could not start.
#[derive(Debug, thiserror::Error)]
pub enum ServerError {
    #[error("cannot listen on {addr}: {source}")]
    Bind {
        addr: SocketAddr,
        source: std::io::Error,
    },
    #[error("cannot start the server runtime: {0}")]
    Runtime(std::io::Error),
    #[error("bad banner version: {0}")]
    Banner(#[from] crate::wire::BannerError),
    #[error("device {addr} added to robot {robot}, but there are only {robots} robots")]
    NoSuchRobot {
        addr: DevAddr,
        robot: usize,
        robots: usize,
    },
}

/// How long dropping a [`Server`] waits for its sessions and listeners to close.
const SHUTDOWN_WAIT: Duration = Duration::from_secs(2);

/// A running server; stops when dropped.
pub struct Server {
    ports: Vec<u16>,
    state: Arc<ServerState>,
    runtime: Mutex<Option<tokio::runtime::Runtime>>,
}

impl Server {
    /// Binds every port, then serves in the background (its own runtime and threads).
    pub fn start(config: ServerConfig) -> Result<Server, ServerError> {
        let banner = Banner::new(&config.version)?;
        let mut listeners = Vec::new();
        for &port in &config.ports {
            let addr = SocketAddr::new(config.bind, port);
            let listener = std::net::TcpListener::bind(addr)
                .map_err(|source| ServerError::Bind { addr, source })?;
            listener
                .set_nonblocking(true)
                .map_err(|source| ServerError::Bind { addr, source })?;
            listeners.push(listener);
        }
        let ports: Vec<u16> = listeners
            .iter()
            .map(|l| l.local_addr().map(|a| a.port()).unwrap_or(0))
            .collect();
        let host = match config.bind {
            IpAddr::V4(ip) if !ip.is_unspecified() => DevAddr::host_from_ipv4(ip),
            _ => DevAddr::host_from_ipv4(Ipv4Addr::LOCALHOST),
        };
        let robots = ports.len();
        let devices = config
            .devices
            .into_iter()
            .map(|(robot, addr, device)| {
                let port = *ports.get(robot).ok_or(ServerError::NoSuchRobot {
                    addr,
                    robot,
                    robots,
                })?;
                let addr = DevAddr {
                    host,
                    robot: u32::from(port),
                    ..addr
                };
                Ok(DeviceSlot::new(addr, device))
            })
            .collect::<Result<Vec<_>, ServerError>>()?;
        let state = Arc::new(ServerState {
            host,
            by_addr: ServerState::index_devices(&devices),
            devices,
            sessions: Mutex::default(),
            gate: CommandGate::new(config.commanders),
            lockstep: config.lockstep,
            queue_rules: config.queue_rules,
            next_peer: AtomicU64::new(0),
            open: Mutex::new(0),
            open_changed: Condvar::new(),
        });
        let runtime = tokio::runtime::Builder::new_multi_thread()
            .worker_threads(2)
            .thread_name(config.thread_name)
            .enable_all()
            .build()
            .map_err(ServerError::Runtime)?;
        for (listener, &port) in listeners.into_iter().zip(&ports) {
            let state = state.clone();
            let banner = banner.clone();
            let max_body = config.max_body;
            let send_buffer = config.send_buffer;
            let publisher_writes = config.publisher_writes;
            runtime.spawn(async move {
                let listener = match tokio::net::TcpListener::from_std(listener) {
                    Ok(l) => l,
                    Err(e) => {
                        tracing::error!(port, "cannot serve: {e}");
                        return;
                    }
                };
                loop {
                    match listener.accept().await {
                        Ok((stream, _)) => {
                            if let Some(bytes) = send_buffer
                                && let Err(e) =
                                    socket2::SockRef::from(&stream).set_send_buffer_size(bytes)
                            {
                                tracing::warn!(port, "cannot size the send buffer: {e}");
                            }
                            tokio::spawn(session::serve(
                                stream,
                                port,
                                state.clone(),
                                banner.clone(),
                                max_body,
                                publisher_writes,
                            ));
                        }
                        Err(e) => {
                            tracing::warn!(port, "accept failed: {e}");
                            tokio::time::sleep(Duration::from_millis(50)).await;
                        }
                    }
                }
            });
        }
        Ok(Server {
            ports,
            state,
            runtime: Mutex::new(Some(runtime)),
        })
    }

    /// The port robot number `robot` is served on.
    pub fn port(&self, robot: usize) -> u16 {
        self.ports[robot]
    }

    pub fn ports(&self) -> &[u16] {
        &self.ports
    }

    /// Publishes device data from any thread.
    pub fn publisher(&self) -> Publisher {
        Publisher {
            state: self.state.clone(),
        }
    }

    /// Client connections being served now.
    pub fn connections(&self) -> usize {
        self.state.open_connections()
    }

    /// Waits until the number of connections satisfies `done`, at most `timeout`; returns it
    /// if it did. Woken by every connection that opens or closes, never polling.
    pub fn wait_for_connections(
        &self,
        timeout: Duration,
        done: impl Fn(usize) -> bool,
    ) -> Option<usize> {
        self.state.wait_for_open(Instant::now() + timeout, done)
    }

    /// Stops accepting and drops every connection.
    pub fn shutdown(&self) {
        if let Some(runtime) = self.runtime.lock().expect("runtime").take() {
            for session in self.state.all_sessions() {
                session.close();
            }
            // Outside an async context, wait (briefly) for the workers to drop every task, so
            // the listening sockets are closed when this returns and the ports can be bound
            // again at once — a restarted server on the same port is what a client reconnects to.
            // Inside one, blocking is not allowed: let the runtime wind down on its own.
            if tokio::runtime::Handle::try_current().is_ok() {
                runtime.shutdown_background();
            } else {
                runtime.shutdown_timeout(SHUTDOWN_WAIT);
            }
        }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        self.shutdown();
    }
}

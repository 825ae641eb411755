//! # player-relay: many observers, one connection per robot
//!
//! A classroom or a demo wants hundreds of viewers on a handful of robots; a Player server
//! serves every client itself, so each viewer costs the robot's own machine a connection,
//! a queue and the encoding of every message. The relay takes that load off the robots:
//!
//! * **upstream** — one `player_proto::client::Client` per robot server (read-only unless a
//!   commander is allowed), subscribing to a device when its first observer does, and
//!   reconnecting when the robot's server goes away;
//! * **downstream** — per robot, a `player_proto::server` on a port of the relay, serving the
//!   robot's devices to any Player client over the ordinary protocol ([`downstream`]);
//! * newest data per device: every observer's queue starts with a replace rule, and each
//!   connection's kernel send buffer is small, so a slow observer gets fresh data rather than
//!   a backlog, and nobody waits for it;
//! * read-only by default: observers may subscribe and read geometry, but their commands and
//!   configuration requests are refused (see `player_proto::server::Commanders`); one
//!   designated controller may command.
//!
//! When a robot's server goes away, the relay drops that robot's observers and stops
//! listening on its port until the robot is back: observers see their server go and come back,
//! as they would without the relay.
//!
//! ## Foxglove and Lichtblick
//!
//! `player-relay --foxglove PORT` also serves every robot over Foxglove's WebSocket protocol
//! (`player_foxglove::live::FoxgloveLive`, one of the [`Front`]s in [`RelayConfig::fronts`]):
//! in Foxglove or Lichtblick, *Open connection* → *Foxglove WebSocket* → `ws://HOST:PORT`
//! (HOST the relay's `--bind`). Each device is a channel in Foxglove's well-known schemas
//! (`LaserScan`, `PoseInFrame`, `FrameTransform`, `Grid`, images, `SceneUpdate`, `Log`), with
//! the frame tree `world` → robot → sensor; what comes once is re-sent to each new subscriber.

pub mod downstream;
mod relayed_device;
pub mod robot;
pub mod subscriptions;
mod survey;
mod wakes;
pub mod world;

use std::net::{IpAddr, Ipv4Addr, SocketAddr, TcpListener};
use std::sync::Arc;
use std::time::{Duration, Instant};

use player_proto::RobotId;
use player_proto::client::{ClientOptions, ConnectError, ConnectionTap, Tap, fan_out};
use player_proto::server::Commanders;

pub use downstream::DownstreamOptions;
pub use player_front::{Front, Watch, Watching};
pub use robot::RelayedRobot;
use subscriptions::Subscriptions;

/// Kernel send buffer of each observer's connection: a few laser scans. More only lets stale
/// data wait in the kernel for a slow observer.
pub const DEFAULT_SEND_BUFFER: usize = 64 * 1024;

/// Why the relay could not start.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RelayError {
    #[error("no robot to relay")]
    NoRobots,
    #[error("cannot start the upstream client: {0}")]
    Upstream(#[from] ConnectError),
    #[error("cannot start a relay thread: {0}")]
    Thread(#[source] std::io::Error),
    /// Two robots given one name: every front would show them as one.
    #[error("two robots are named {0}")]
    SameName(String),
    /// A robot's observer port is taken (or not this machine's): the relay would otherwise
    /// run without serving that robot to anyone.
    #[error("cannot listen for observers on {addr}: {source}")]
    Listen {
        addr: SocketAddr,
        source: std::io::Error,
    },
}

/// One robot (its server, and its name where it has one) and the relay port its observers
/// connect to.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Route {
    pub robot: RobotId,
    /// 0: any free port (see [`RelayedRobot::listen_port`]).
    pub listen_port: u16,
}

impl Route {
    /// A robot server on this machine, relayed on any free port: what tests and benchmarks
    /// with a simulation beside them want.
    pub fn loopback(port: u16) -> Route {
        Route {
            robot: RobotId::new("127.0.0.1", port),
            listen_port: 0,
        }
    }
}

/// What to relay, and how.
#[derive(Clone)]
pub struct RelayConfig {
    pub routes: Vec<Route>,
    /// Where observers connect; loopback by default.
    pub bind: IpAddr,
    /// Who may command; nobody by default.
    pub commanders: Commanders,
    pub send_buffer: usize,
    /// The upstream clients' options (timeouts, backoff); `read_only`, `notifier` and `tap`
    /// are the relay's.
    pub upstream: ClientOptions,
    /// Fronts that are not Player clients (the web page, Foxglove, Zenoh): the relay drives
    /// each alike ([`Front`]): every robot as it arrives, by its [`RobotId`], everything its
    /// server sends the relay, its leaving, and the stop. With any front, the relay subscribes
    /// to every device of a robot and asks what describes them (geometries, map tiles) each
    /// time it connects, since nobody downstream will ask for it.
    pub fronts: Vec<Arc<dyn Front>>,
    /// Whether a front passes commands on to the robots (Zenoh's authorised controller), so
    /// the upstream clients must not be read-only even when no observer may command.
    pub fronts_command: bool,
}

impl std::fmt::Debug for RelayConfig {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RelayConfig")
            .field("routes", &self.routes)
            .field("bind", &self.bind)
            .field("commanders", &self.commanders)
            .field("send_buffer", &self.send_buffer)
            .field("upstream", &self.upstream)
            .field(
                "fronts",
                &self.fronts.iter().map(|f| f.name()).collect::<Vec<_>>(),
            )
            .field("fronts_command", &self.fronts_command)
            .finish()
    }
}

impl Default for RelayConfig {
    fn default() -> Self {
        RelayConfig {
            routes: Vec::new(),
            bind: IpAddr::V4(Ipv4Addr::LOCALHOST),
            commanders: Commanders::Nobody,
            send_buffer: DEFAULT_SEND_BUFFER,
            upstream: ClientOptions::default(),
            fronts: Vec::new(),
            fronts_command: false,
        }
    }
}

/// A running relay; stops when dropped (its robots, then its fronts).
pub struct Relay {
    robots: Vec<RelayedRobot>,
    fronts: Vec<Arc<dyn Front>>,
}

impl Relay {
    /// Starts a client per robot; each robot is served downstream as soon as its server
    /// answers (see [`Relay::wait_serving`]).
    pub fn start(config: RelayConfig) -> Result<Relay, RelayError> {
        if config.routes.is_empty() {
            return Err(RelayError::NoRobots);
        }
        check_listen_ports(config.bind, &config.routes)?;
        check_names(&config.routes)?;
        let downstream = DownstreamOptions {
            bind: config.bind,
            commanders: config.commanders,
            send_buffer: config.send_buffer,
        };
        let upstream = ClientOptions {
            // A relay nobody may command cannot move a robot, whatever goes wrong above it.
            read_only: config.commanders == Commanders::Nobody && !config.fronts_command,
            // The newest scan is all an observer gets: the robot need not queue older ones.
            replace_old_data: true,
            ..config.upstream
        };
        let survey = !config.fronts.is_empty();
        let robots = config
            .routes
            .iter()
            .map(|route| {
                // A robot arrived: each front hears of it as the route names it.
                let taps = config.fronts.iter().map(|front| {
                    let tap: ConnectionTap = front.arrived(&route.robot);
                    Arc::new(move |_: &str, _: u16| tap.clone()) as Tap
                });
                let upstream = ClientOptions {
                    tap: fan_out(taps.collect()),
                    ..upstream.clone()
                };
                RelayedRobot::start(
                    &route.robot,
                    route.listen_port,
                    upstream,
                    downstream.clone(),
                    survey,
                    Arc::new(Subscriptions::default()),
                )
            })
            .collect::<Result<Vec<_>, _>>()?;
        for front in &config.fronts {
            for robot in &robots {
                front.commands_through(robot.id(), robot.upstream().clone());
                // What the front's viewers look at is what the relay subscribes to.
                let watch = Watch::new(robot.subscriptions().clone());
                if front.watch(robot.id(), watch) == Watching::Everything {
                    robot.subscriptions().watch_everything();
                }
            }
        }
        Ok(Relay {
            robots,
            fronts: config.fronts,
        })
    }

    pub fn robots(&self) -> &[RelayedRobot] {
        &self.robots
    }

    /// Waits until every robot is served downstream, at most `timeout`; returns how many are.
    pub fn wait_serving(&self, timeout: Duration) -> usize {
        let deadline = Instant::now() + timeout;
        self.robots
            .iter()
            .filter(|r| r.wait_serving(true, deadline.saturating_duration_since(Instant::now())))
            .count()
    }

    /// Observers connected now, over all robots.
    pub fn observers(&self) -> usize {
        self.robots.iter().map(RelayedRobot::observers).sum()
    }
}

impl Drop for Relay {
    fn drop(&mut self) {
        // Every robot's thread ends first: no front hears of a robot after its stop.
        self.robots.clear();
        for front in &self.fronts {
            front.stop();
        }
    }
}

/// Binds every fixed observer port of `routes` on `bind` once, all at the same time (two
/// robots given one port fail too), and lets them go: a port taken now is refused before
/// anything starts rather than tried again each time its robot connects. [`Relay::start`]
/// checks; a program may check sooner, before it starts anything else.
pub fn check_listen_ports(bind: IpAddr, routes: &[Route]) -> Result<(), RelayError> {
    let mut held = Vec::new();
    for route in routes.iter().filter(|r| r.listen_port != 0) {
        let addr = SocketAddr::new(bind, route.listen_port);
        let listener =
            TcpListener::bind(addr).map_err(|source| RelayError::Listen { addr, source })?;
        held.push(listener);
    }
    Ok(())
}

/// Refuses two routes with one name (two unnamed robots are told apart by their servers).
fn check_names(routes: &[Route]) -> Result<(), RelayError> {
    let mut names = std::collections::HashSet::new();
    for name in routes.iter().filter_map(|r| r.robot.name()) {
        if !names.insert(name) {
            return Err(RelayError::SameName(name.to_string()));
        }
    }
    Ok(())
}

//! # player-web: Player robots in any browser
//!
//! `player-relay --web PORT` serves a page at `http://host:PORT/`: a live top view of every
//! robot the relay carries (bodies, lasers, rangers, sonars, fiducials, the map, localize
//! estimates, planner goals) and a row per robot (link, rate and age per device), with
//! nothing to install. The relay's controller (`--controller IP`, `--first-to-command`) may
//! select a robot and click a goal or drive it with the arrow keys; everyone else watches.
//!
//! * [`hub`] — fed by the relay's upstream taps; every message becomes JSON once, in
//!   player-proto's own types ([`page`]), kept newest-per-device for pages that open later
//!   and broadcast to those open;
//! * [`socket`] — one task per page: a page that falls behind gets the newest of everything
//!   instead of a backlog; one that stops reading is closed after
//!   [`player_front::STALLED_AFTER`], as every front's viewers are;
//! * [`control`] — the same command rule as the relay's Player ports, and a dead-man stop;
//! * [`http`] — the page, its script and style, compiled in (no CDN, no internet needed);
//! * [`walls`] — the world's walls, where the relay knows them (the world it simulates);
//! * [`views`] — what the open pages show: every robot's pose, and the sensors of the robots
//!   in a page's view (at most [`views::SENSORS_IN_VIEW`]); the relay subscribes to that
//!   alone, and nothing while no page is open.

pub mod control;
pub mod http;
pub mod hub;
pub mod page;
pub mod refused;
pub mod socket;
pub mod views;
pub mod walls;

use std::net::{IpAddr, SocketAddr};
use std::sync::Arc;
use std::time::Duration;

use tokio::runtime::Handle;

use player_front::{Front, FrontRuntime, Watch, Watching};
use player_proto::RobotId;
use player_proto::client::{Client, ConnectionTap, RobotTap, Tap, unnamed};
use player_proto::server::Commanders;

use control::Control;
use hub::Hub;

/// How often the pages get their status rows.
pub const STATUS_EVERY: Duration = Duration::from_secs(1);

/// Why the page cannot be served.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum WebError {
    #[error("cannot listen for the web page on {addr}: {source}")]
    Bind {
        addr: SocketAddr,
        source: std::io::Error,
    },
    #[error("cannot start the web page's runtime: {0}")]
    Runtime(std::io::Error),
}

/// The web page, served on its own runtime or a handed one until stopped or dropped.
pub struct WebFront {
    hub: Arc<Hub>,
    control: Arc<Control>,
    port: u16,
    runtime: FrontRuntime,
}

impl WebFront {
    /// Listens on `bind:port` (0: any free port) and serves the page on a runtime of its own;
    /// robots appear as the relay's clients reach them through [`WebFront::tap`].
    pub fn start(bind: IpAddr, port: u16, rule: Commanders) -> Result<WebFront, WebError> {
        let runtime = FrontRuntime::own("web-page", 2).map_err(WebError::Runtime)?;
        WebFront::serve(runtime, bind, port, rule)
    }

    /// As [`WebFront::start`], on the runtime of `handle` (the relay's for all its fronts,
    /// or an embedding program's): dropping the front closes its pages and its listener and
    /// leaves that runtime running.
    pub fn start_on(
        handle: Handle,
        bind: IpAddr,
        port: u16,
        rule: Commanders,
    ) -> Result<WebFront, WebError> {
        WebFront::serve(FrontRuntime::on(handle), bind, port, rule)
    }

    fn serve(
        runtime: FrontRuntime,
        bind: IpAddr,
        port: u16,
        rule: Commanders,
    ) -> Result<WebFront, WebError> {
        let addr = SocketAddr::new(bind, port);
        let listener = player_front::socket::listen(addr, PAGE_SEND_BUFFER)
            .and_then(|std| {
                let _entered = runtime.handle().enter();
                tokio::net::TcpListener::from_std(std)
            })
            .map_err(|source| WebError::Bind { addr, source })?;
        let port = listener.local_addr().map_or(port, |a| a.port());
        let hub = Arc::new(Hub::default());
        let control = Arc::new(Control::new(rule));
        let app = http::router(hub.clone(), control.clone(), runtime.stopping())
            .into_make_service_with_connect_info::<SocketAddr>();
        // Small frames (poses, commands) go out at once rather than waiting for company.
        let listener = axum::serve::ListenerExt::tap_io(listener, |tcp| {
            if let Err(e) = tcp.set_nodelay(true) {
                tracing::debug!("a page's socket keeps Nagle: {e}");
            }
        });
        runtime.spawn(async move {
            if let Err(e) = axum::serve(listener, app).await {
                tracing::error!("the web page stopped: {e}");
            }
        });
        let ticking = hub.clone();
        runtime.spawn(async move {
            let mut tick = tokio::time::interval(STATUS_EVERY);
            loop {
                tick.tick().await;
                ticking.broadcast_rows();
            }
        });
        Ok(WebFront {
            hub,
            control,
            port,
            runtime,
        })
    }

    /// Tasks of the page running now (its listener, its status rows; pages are not counted).
    pub fn tasks(&self) -> usize {
        self.runtime.tasks()
    }

    /// The port the page is served on.
    pub fn port(&self) -> u16 {
        self.port
    }

    /// The tap to give the relay (`RelayConfig::fronts`): robots shown by their names.
    pub fn robot_tap(&self) -> RobotTap {
        self.hub.robot_tap()
    }

    /// A tap for Player clients that know no names (pv3d's): robots shown as `host:port`.
    pub fn tap(&self) -> Tap {
        unnamed(self.robot_tap())
    }

    /// Devices the open pages look at now, over every robot.
    pub fn looks(&self) -> usize {
        self.hub.looks()
    }

    /// Draws `walls` (the world's, where the relay knows them) under the robots.
    pub fn set_walls(&self, walls: &walls::Walls) {
        self.hub.set_walls(walls);
    }

    /// Makes a robot commandable from the page (by the controller only), as `host:port`.
    pub fn add_robot(&self, client: Arc<Client>) {
        self.add_robot_as(RobotId::new(client.host(), client.port()), client);
    }

    /// Makes the relayed robot `id` commandable from the page (by the controller only).
    pub fn add_robot_as(&self, id: RobotId, client: Arc<Client>) {
        self.control.add_robot(id, client);
    }
}

/// The page as one of the relay's fronts: robots shown by their names, the controller's
/// commands sent through the relay's clients.
impl Front for WebFront {
    fn name(&self) -> &str {
        "web page"
    }

    fn arrived(&self, robot: &RobotId) -> ConnectionTap {
        (self.robot_tap())(robot)
    }

    fn commands_through(&self, robot: &RobotId, client: Arc<Client>) {
        self.add_robot_as(robot.clone(), client);
    }

    fn watch(&self, robot: &RobotId, watch: Watch) -> Watching {
        self.hub.watch(robot, watch);
        Watching::AsLooked
    }

    /// Pages closed (1001), the listener closed; the runtime, if handed, runs on.
    fn stop(&self) {
        self.runtime.stop();
    }
}

/// Kernel send buffer per page: a few frames of a few robots. A page that stops reading
/// fills it in a moment and is closed (see [`player_front::STALLED_AFTER`]) instead of
/// holding megabytes of stale frames.
pub const PAGE_SEND_BUFFER: usize = 64 * 1024;

//! The robot manager: one client per Player server (host:port), shared — reference counted —
//! by every plugin that uses a device on it. A server that goes away shows as reconnecting;
//! the others carry on. A few robots get a thread each; a swarm's share a few I/O threads.

use std::sync::Arc;
use std::time::Duration;

use framework::config::DeviceRef;
use framework::device::DeviceAccess;
use player_proto::client::{
    Client, ClientOptions, ConnectionState, MultiClient, Notifier, SharedIo, Tap,
};

use super::device_links::{DeviceLinks, LinkKey};
use crate::composition::ClientDecl;

/// Silence after which a server is asked whether it is still there (a device-list request it
/// always answers); no answer, and the connection is dropped and re-established.
const STALL_TIMEOUT: Duration = Duration::from_secs(3);

/// From this many servers up, their connections share [`SHARED_IO_THREADS`] threads instead
/// of a thread each: a thousand robots' steps then wake a few threads, not a thousand.
const SHARED_IO_FROM: usize = 16;
const SHARED_IO_THREADS: usize = 1;

/// How the viewer uses the robots.
#[derive(Clone, Default)]
pub struct RobotOptions {
    /// Read-only clients: the viewer watches, never commands or configures a robot.
    pub observe: bool,
    /// Shown every message of every connection (`pv3d --record`).
    pub tap: Option<Tap>,
}

/// Every Player server of a composition: player-proto's [`MultiClient`] (one client per
/// server), with the viewer's options and the device links plugins share.
pub struct RobotManager {
    clients: MultiClient,
    /// Every client is read-only (`pv3d --observe`).
    observing: bool,
    /// The device links plugins hold, shared by plugins of the same device.
    links: DeviceLinks,
}

impl RobotManager {
    /// Starts a client for each server (at once, in their own threads); `notifier` runs when
    /// any of them stored new data.
    pub fn start(servers: &[ClientDecl], notifier: Option<Notifier>) -> RobotManager {
        RobotManager::start_with(servers, notifier, RobotOptions::default())
    }

    /// [`RobotManager::start`] with the viewer's choices.
    pub fn start_with(
        servers: &[ClientDecl],
        notifier: Option<Notifier>,
        robot_options: RobotOptions,
    ) -> RobotManager {
        let mut clients = MultiClient::new();
        let shared_io = (servers.len() >= SHARED_IO_FROM)
            .then(|| SharedIo::new(SHARED_IO_THREADS))
            .and_then(|io| {
                io.inspect_err(|e| tracing::warn!("a thread per robot: no shared I/O: {e}"))
                    .ok()
            });
        for server in servers {
            let options = ClientOptions {
                notifier: notifier.clone(),
                read_only: robot_options.observe,
                // A viewer must show a robot whose server hangs, not its last data forever.
                stall_timeout: Some(STALL_TIMEOUT),
                tap: robot_options.tap.clone(),
                shared_io: shared_io.clone(),
                ..ClientOptions::default()
            };
            if let Err(e) = clients.add(&server.host, server.port, options) {
                tracing::error!("{}: {e}", server.pos);
            }
        }
        RobotManager {
            clients,
            observing: robot_options.observe,
            links: Default::default(),
        }
    }

    /// Whether the viewer only observes: no command or configuration request leaves it.
    pub fn observing(&self) -> bool {
        self.observing
    }

    /// Waits until every server has answered its handshake or failed, at most `timeout`.
    pub fn wait_for_handshakes(&self, timeout: Duration) {
        self.clients.wait_for_handshakes(timeout);
        for client in self.clients.iter() {
            let state = client.state();
            if state != ConnectionState::Connected {
                tracing::warn!(
                    "{}:{} is {state}; its devices appear when it answers",
                    client.host(),
                    client.port()
                );
            }
        }
    }

    /// The shared client of a server.
    pub fn client(&self, host: &str, port: u16) -> Option<&Arc<Client>> {
        self.clients.find(host, port)
    }

    pub fn clients(&self) -> impl Iterator<Item = (&str, u16, &Arc<Client>)> {
        self.clients.iter().map(|c| (c.host(), c.port(), c))
    }

    /// The devices plugins use now, by server.
    pub fn used_devices(&self) -> Vec<LinkKey> {
        self.links.held()
    }

    /// Whether every server is connected and every device a plugin uses has sent data: what
    /// the next frame draws is the whole picture (`--frame-stats` times the first such frame).
    pub fn all_reporting(&self) -> bool {
        let connected = (self.clients.iter()).all(|c| c.state() == ConnectionState::Connected);
        connected
            && self.links.held().iter().all(|(host, port, addr)| {
                self.client(host, *port)
                    .is_some_and(|c| c.stats(*addr).messages > 0)
            })
    }

    /// Access to a plugin's device, shared by the plugins of the same device: the first one
    /// subscribes, and when the last one drops its handle the device is unsubscribed.
    pub fn device(&self, device: &DeviceRef) -> Option<Arc<dyn DeviceAccess>> {
        let client = self.client(&device.host, device.port)?;
        let key = (device.host.clone(), device.port, device.addr);
        Some(self.links.link(client, key))
    }
}

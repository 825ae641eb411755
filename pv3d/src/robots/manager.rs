//! The robot manager: one client thread per Player server (host:port), shared — reference
//! counted — by every plugin that uses a device on it. A server that goes away shows as
//! reconnecting; the others carry on.

use std::sync::Arc;
use std::time::Duration;

use framework::config::DeviceRef;
use framework::device::DeviceAccess;
use player_proto::client::{Client, ClientOptions, ConnectionState, MultiClient, Notifier};

use super::device_links::{DeviceLinks, LinkKey};
use crate::composition::ClientDecl;

/// Silence after which a server is asked whether it is still there (a device-list request it
/// always answers); no answer, and the connection is dropped and re-established.
const STALL_TIMEOUT: Duration = Duration::from_secs(3);

/// Every Player server of a composition: player-proto's [`MultiClient`] (one client per
/// server), with the viewer's options and the device links plugins share.
pub struct RobotManager {
    clients: MultiClient,
    /// The device links plugins hold, shared by plugins of the same device.
    links: DeviceLinks,
}

impl RobotManager {
    /// Starts a client for each server (at once, in their own threads); `notifier` runs when
    /// any of them stored new data.
    pub fn start(servers: &[ClientDecl], notifier: Option<Notifier>) -> RobotManager {
        let mut clients = MultiClient::new();
        for server in servers {
            let options = ClientOptions {
                notifier: notifier.clone(),
                // A viewer must show a robot whose server hangs, not its last data forever.
                stall_timeout: Some(STALL_TIMEOUT),
                ..ClientOptions::default()
            };
            if let Err(e) = clients.add(&server.host, server.port, options) {
                tracing::error!("{}: {e}", server.pos);
            }
        }
        RobotManager {
            clients,
            links: Default::default(),
        }
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

    /// Access to a plugin's device, shared by the plugins of the same device: the first one
    /// subscribes, and when the last one drops its handle the device is unsubscribed.
    pub fn device(&self, device: &DeviceRef) -> Option<Arc<dyn DeviceAccess>> {
        let client = self.client(&device.host, device.port)?;
        let key = (device.host.clone(), device.port, device.addr);
        Some(self.links.link(client, key))
    }
}

//! The robot manager: one client thread per Player server (host:port), shared — reference
//! counted — by every plugin that uses a device on it. A server that goes away shows as
//! reconnecting; the others carry on.

use std::collections::HashMap;
use std::sync::Arc;
use std::time::Duration;

use framework::config::DeviceRef;
use framework::device::DeviceAccess;
use player_proto::client::{Client, ClientOptions, ConnectionState, MultiClient, Notifier, Tap};

use super::device_link::ClientDevice;
use crate::composition::{ClientDecl, FoundDevice};

/// Silence after which a server is asked whether it is still there (a device-list request it
/// always answers); no answer, and the connection is dropped and re-established.
const STALL_TIMEOUT: Duration = Duration::from_secs(3);

/// Every Player server of a composition: player-proto's [`MultiClient`] (one client per
/// server), with the viewer's options and the device links plugins share.
pub struct RobotManager {
    clients: MultiClient,
    links: std::sync::Mutex<HashMap<(String, u16, player_proto::DevAddr), Arc<ClientDevice>>>,
}

impl RobotManager {
    /// Starts a client for each server (at once, in their own threads); `notifier` runs when
    /// any of them stored new data.
    pub fn start(servers: &[ClientDecl], notifier: Option<Notifier>) -> RobotManager {
        RobotManager::start_tapped(servers, notifier, None)
    }

    /// [`RobotManager::start`] with every connection's messages shown to `tap` (a recorder).
    pub fn start_tapped(
        servers: &[ClientDecl],
        notifier: Option<Notifier>,
        tap: Option<Tap>,
    ) -> RobotManager {
        let mut clients = MultiClient::new();
        for server in servers {
            let options = ClientOptions {
                notifier: notifier.clone(),
                // A viewer must show a robot whose server hangs, not its last data forever.
                stall_timeout: Some(STALL_TIMEOUT),
                tap: tap.clone(),
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

    /// The devices every connected server reported.
    pub fn devices(&self) -> Vec<FoundDevice> {
        self.clients
            .iter()
            .flat_map(|client| {
                client.devices().into_iter().map(move |d| FoundDevice {
                    host: client.host().to_string(),
                    port: client.port(),
                    addr: d.addr,
                    driver: d.driver,
                })
            })
            .collect()
    }

    /// The shared client of a server.
    pub fn client(&self, host: &str, port: u16) -> Option<&Arc<Client>> {
        self.clients.find(host, port)
    }

    pub fn clients(&self) -> impl Iterator<Item = (&str, u16, &Arc<Client>)> {
        self.clients.iter().map(|c| (c.host(), c.port(), c))
    }

    /// The devices plugins use, by server.
    pub fn used_devices(&self) -> Vec<(String, u16, player_proto::DevAddr)> {
        let mut used: Vec<_> = self.links.lock().expect("links").keys().cloned().collect();
        used.sort();
        used
    }

    /// Access to a plugin's device (subscribing on first use; shared by plugins of the same
    /// device).
    pub fn device(&self, device: &DeviceRef) -> Option<Arc<dyn DeviceAccess>> {
        let client = self.client(&device.host, device.port)?.clone();
        let key = (device.host.clone(), device.port, device.addr);
        let mut links = self.links.lock().expect("links");
        let link = links
            .entry(key)
            .or_insert_with(|| Arc::new(ClientDevice::new(client, device.addr)))
            .clone();
        Some(link)
    }
}

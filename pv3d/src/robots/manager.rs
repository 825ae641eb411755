//! The robot manager: one client thread per Player server (host:port), shared — reference
//! counted — by every plugin that uses a device on it. A server that goes away shows as
//! reconnecting; the others carry on.

use std::collections::HashMap;
use std::sync::Arc;
use std::time::{Duration, Instant};

use framework::config::DeviceRef;
use framework::device::DeviceAccess;
use player_proto::client::{Client, ClientOptions, ConnectionState, Notifier};

use super::device_link::ClientDevice;
use crate::composition::{ClientDecl, FoundDevice};

/// Silence after which a server is asked whether it is still there (a device-list request it
/// always answers); no answer, and the connection is dropped and re-established.
const STALL_TIMEOUT: Duration = Duration::from_secs(3);

/// Every Player server of a composition.
pub struct RobotManager {
    clients: Vec<(String, u16, Arc<Client>)>,
    links: std::sync::Mutex<HashMap<(String, u16, player_proto::DevAddr), Arc<ClientDevice>>>,
}

impl RobotManager {
    /// Starts a client for each server (at once, in their own threads); `notifier` runs when
    /// any of them stored new data.
    pub fn start(servers: &[ClientDecl], notifier: Option<Notifier>) -> RobotManager {
        let mut clients = Vec::new();
        for server in servers {
            if clients
                .iter()
                .any(|(h, p, _)| *h == server.host && *p == server.port)
            {
                continue;
            }
            let options = ClientOptions {
                notifier: notifier.clone(),
                // A viewer must show a robot whose server hangs, not its last data forever.
                stall_timeout: Some(STALL_TIMEOUT),
                ..ClientOptions::default()
            };
            match Client::spawn(&server.host, server.port, options) {
                Ok(c) => clients.push((server.host.clone(), server.port, Arc::new(c))),
                Err(e) => tracing::error!("{}: {e}", server.pos),
            }
        }
        RobotManager {
            clients,
            links: Default::default(),
        }
    }

    /// Waits until every server has answered its handshake or failed, at most `timeout`.
    pub fn wait_for_handshakes(&self, timeout: Duration) {
        let deadline = Instant::now() + timeout;
        while Instant::now() < deadline
            && self
                .clients
                .iter()
                .any(|(_, _, c)| c.state() == ConnectionState::Connecting)
        {
            std::thread::sleep(Duration::from_millis(10));
        }
        for (host, port, client) in &self.clients {
            if client.state() != ConnectionState::Connected {
                tracing::warn!(
                    "{host}:{port} is {}; its devices appear when it answers",
                    client.state()
                );
            }
        }
    }

    /// The devices every connected server reported.
    pub fn devices(&self) -> Vec<FoundDevice> {
        self.clients
            .iter()
            .flat_map(|(host, port, client)| {
                client.devices().into_iter().map(move |d| FoundDevice {
                    host: host.clone(),
                    port: *port,
                    addr: d.addr,
                    driver: d.driver,
                })
            })
            .collect()
    }

    /// The shared client of a server.
    pub fn client(&self, host: &str, port: u16) -> Option<&Arc<Client>> {
        self.clients
            .iter()
            .find(|(h, p, _)| h == host && *p == port)
            .map(|(_, _, c)| c)
    }

    pub fn clients(&self) -> impl Iterator<Item = (&str, u16, &Arc<Client>)> {
        self.clients.iter().map(|(h, p, c)| (h.as_str(), *p, c))
    }

    /// Access to a plugin's device (subscribing on first use; shared by plugins of the same
    /// device).
    /// The devices plugins use, by server.
    pub fn used_devices(&self) -> Vec<(String, u16, player_proto::DevAddr)> {
        let mut used: Vec<_> = self.links.lock().expect("links").keys().cloned().collect();
        used.sort();
        used
    }

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

//! Many robots at once: one client (one thread) per server, none waiting for another.

use std::sync::Arc;
use std::time::{Duration, Instant};

use super::{Client, ClientOptions, ConnectError, ConnectionState};

/// A set of clients, one per (host, port), each shareable with whatever uses its devices.
#[derive(Default)]
pub struct MultiClient {
    clients: Vec<Arc<Client>>,
}

impl MultiClient {
    pub fn new() -> MultiClient {
        MultiClient::default()
    }

    /// Starts a client for `host:port` (returns at once; it connects in its own thread) and
    /// returns its index. A server already in the set is not connected twice.
    pub fn add(
        &mut self,
        host: &str,
        port: u16,
        options: ClientOptions,
    ) -> Result<usize, ConnectError> {
        if let Some(i) = self.position(host, port) {
            return Ok(i);
        }
        self.clients
            .push(Arc::new(Client::spawn(host, port, options)?));
        Ok(self.clients.len() - 1)
    }

    fn position(&self, host: &str, port: u16) -> Option<usize> {
        self.clients
            .iter()
            .position(|c| c.host() == host && c.port() == port)
    }

    pub fn get(&self, index: usize) -> Option<&Arc<Client>> {
        self.clients.get(index)
    }

    pub fn find(&self, host: &str, port: u16) -> Option<&Arc<Client>> {
        self.position(host, port).map(|i| &self.clients[i])
    }

    pub fn iter(&self) -> impl Iterator<Item = &Arc<Client>> {
        self.clients.iter()
    }

    pub fn len(&self) -> usize {
        self.clients.len()
    }

    pub fn is_empty(&self) -> bool {
        self.clients.is_empty()
    }

    /// How many clients are connected right now.
    pub fn connected(&self) -> usize {
        self.clients
            .iter()
            .filter(|c| c.state() == ConnectionState::Connected)
            .count()
    }

    /// Waits until every client has finished its first handshake — done, or failed and
    /// retrying — or `timeout` passes; returns how many are connected.
    pub fn wait_for_handshakes(&self, timeout: Duration) -> usize {
        self.wait_for_each(timeout, |s| *s != ConnectionState::Connecting)
    }

    /// Waits until every client is connected or refused for good, or `timeout` passes;
    /// returns how many are connected. Unlike [`MultiClient::wait_for_handshakes`], a server
    /// still starting (its first try refused, retrying) is waited for: a recorder lists and
    /// subscribes the devices once, when its robots have connected.
    pub fn wait_for_connections(&self, timeout: Duration) -> usize {
        self.wait_for_each(timeout, |s| {
            matches!(s, ConnectionState::Connected | ConnectionState::Failed(_))
        })
    }

    /// Waits until every client's state satisfies `done`, or `timeout` passes; returns how
    /// many are connected.
    fn wait_for_each(&self, timeout: Duration, done: impl Fn(&ConnectionState) -> bool) -> usize {
        let deadline = Instant::now() + timeout;
        for client in &self.clients {
            // One deadline for all: the waits overlap, so the whole takes the slowest's time.
            client.wait_until(deadline, &done);
        }
        self.connected()
    }
}

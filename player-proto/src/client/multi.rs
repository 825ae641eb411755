//! Many robots at once: one client (one thread) per server, none waiting for another.

use super::{Client, ClientOptions, ConnectError, ConnectionState};

/// A set of clients, one per (host, port).
#[derive(Default)]
pub struct MultiClient {
    clients: Vec<Client>,
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
        if let Some(i) = self
            .clients
            .iter()
            .position(|c| c.host() == host && c.port() == port)
        {
            return Ok(i);
        }
        self.clients.push(Client::spawn(host, port, options)?);
        Ok(self.clients.len() - 1)
    }

    pub fn get(&self, index: usize) -> Option<&Client> {
        self.clients.get(index)
    }

    pub fn find(&self, host: &str, port: u16) -> Option<&Client> {
        self.clients
            .iter()
            .find(|c| c.host() == host && c.port() == port)
    }

    pub fn iter(&self) -> impl Iterator<Item = &Client> {
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

    /// Waits until every client has finished its first handshake or `timeout` passes; returns
    /// how many are connected.
    pub fn wait_connected(&self, timeout: std::time::Duration) -> usize {
        let deadline = std::time::Instant::now() + timeout;
        while self.connected() < self.clients.len() && std::time::Instant::now() < deadline {
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
        self.connected()
    }
}

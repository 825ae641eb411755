//! What a running server shares between its sessions and its publisher.

use std::collections::{HashMap, HashSet};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard, Weak};
use std::time::Instant;

use bytes::BytesMut;
use tokio::sync::Notify;

use super::control::{CommandGate, Peer};
use super::device::Device;
use super::direct::{DirectWrite, WriterTurn};
use super::queue::OutQueue;
use crate::delivery::ReplaceRule;
use crate::message::Message;
use crate::wire::{DevAddr, Interface};

/// A device and its full address (server host, port, interface, index).
pub(crate) struct DeviceSlot {
    pub addr: DevAddr,
    pub device: Mutex<Box<dyn Device>>,
    /// The connections subscribed to it, in the order they subscribed: kept by the sessions
    /// as they subscribe and leave, so that publishing goes straight to them — asking every
    /// connection of the port whether it subscribed, for every message, was 6 % of a
    /// simulation serving 1 024 robots.
    pub subscribers: Mutex<Vec<Arc<SessionState>>>,
}

impl DeviceSlot {
    pub fn new(addr: DevAddr, device: Box<dyn Device>) -> DeviceSlot {
        DeviceSlot {
            addr,
            device: Mutex::new(device),
            subscribers: Mutex::default(),
        }
    }

    /// The subscribed connections, locked. Taken after the device (by a session subscribing)
    /// and after the device's own locks (by a simulation publishing), and before any queue.
    pub fn subscribers(&self) -> MutexGuard<'_, Vec<Arc<SessionState>>> {
        self.subscribers.lock().expect("subscribers")
    }
}

/// One client connection, as the publisher sees it.
pub(crate) struct SessionState {
    pub port: u16,
    pub peer: Peer,
    pub subscriptions: Mutex<HashSet<(Interface, u16)>>,
    pub queue: Mutex<OutQueue>,
    pub wake_writer: Notify,
    pub closed: AtomicBool,
    /// The publisher's own writes to the socket (see `direct.rs`).
    pub direct: Mutex<DirectWrite>,
}

impl SessionState {
    /// A session whose queue starts with `rules`; `socket`, a second handle on the
    /// connection's socket, lets a publisher write to it (see `direct.rs`).
    pub fn new(
        port: u16,
        peer: Peer,
        rules: &[ReplaceRule],
        socket: Option<std::net::TcpStream>,
    ) -> SessionState {
        let mut queue = OutQueue::default();
        for rule in rules {
            queue.add_rule(*rule);
        }
        SessionState {
            port,
            peer,
            subscriptions: Mutex::default(),
            queue: Mutex::new(queue),
            wake_writer: Notify::new(),
            closed: AtomicBool::new(false),
            direct: Mutex::new(DirectWrite::new(socket)),
        }
    }

    /// Queues a message and wakes the writer.
    pub fn send(&self, message: Arc<Message>) {
        self.queue_only(message);
        self.wake_writer.notify_one();
    }

    /// Queues a message without waking the writer: [`Self::wake`] follows once the rest of
    /// a batch is queued too, so that the batch leaves in one write.
    pub fn queue_only(&self, message: Arc<Message>) {
        self.queue.lock().expect("queue").push(message);
    }

    /// Wakes the writer for what was queued.
    pub fn wake(&self) {
        self.wake_writer.notify_one();
    }

    pub fn is_closed(&self) -> bool {
        self.closed.load(Ordering::Acquire)
    }

    pub fn close(&self) {
        self.closed.store(true, Ordering::Release);
        self.drop_direct_socket();
        self.wake_writer.notify_one();
    }

    /// See [`DirectWrite::flush_now`].
    pub fn flush_now(&self, scratch: &mut BytesMut) {
        DirectWrite::flush_now(&self.direct, &self.queue, || self.wake(), scratch);
    }

    /// See [`DirectWrite::writer_takes`].
    pub fn writer_takes(&self) -> WriterTurn {
        DirectWrite::writer_takes(&self.direct, &self.queue)
    }

    /// See [`DirectWrite::writer_done`].
    pub fn writer_done(&self) {
        DirectWrite::writer_done(&self.direct);
    }

    /// See [`DirectWrite::drop_socket`].
    pub fn drop_direct_socket(&self) {
        DirectWrite::drop_socket(&self.direct);
    }
}

/// Everything the server knows.
pub(crate) struct ServerState {
    /// The `host` value written into addresses (the server's IPv4 address in memory order).
    pub host: u32,
    pub devices: Vec<DeviceSlot>,
    /// Where each device is in `devices`, by (port, interface, index): the first one added
    /// when two share an address.
    pub by_addr: HashMap<(u16, Interface, u16), usize>,
    /// Live connections by port, to close them all when the server stops (publishing goes
    /// through each device's own list of subscribers).
    pub sessions: Mutex<HashMap<u16, Vec<Weak<SessionState>>>>,
    /// Who may command devices.
    pub gate: CommandGate,
    /// Set when the server is a lockstep simulation's.
    pub lockstep: Option<Arc<super::Lockstep>>,
    /// The replace rules every connection's queue starts with.
    pub queue_rules: Vec<ReplaceRule>,
    /// For [`Peer::id`].
    pub next_peer: AtomicU64,
    /// Connections being served, with a signal on every change.
    pub open: Mutex<usize>,
    pub open_changed: Condvar,
}

/// Counts a connection as open while it lives.
pub(crate) struct OpenConnection<'a>(&'a ServerState);

impl<'a> OpenConnection<'a> {
    pub fn new(state: &'a ServerState) -> OpenConnection<'a> {
        *state.lock_open() += 1;
        state.open_changed.notify_all();
        OpenConnection(state)
    }
}

impl Drop for OpenConnection<'_> {
    fn drop(&mut self) {
        *self.0.lock_open() -= 1;
        self.0.open_changed.notify_all();
    }
}

impl ServerState {
    fn lock_open(&self) -> MutexGuard<'_, usize> {
        // A plain counter cannot be left half-written.
        self.open.lock().unwrap_or_else(|e| e.into_inner())
    }

    pub fn open_connections(&self) -> usize {
        *self.lock_open()
    }

    /// Blocks until the number of open connections satisfies `done` or `deadline` passes;
    /// returns the number if it did.
    pub fn wait_for_open(&self, deadline: Instant, done: impl Fn(usize) -> bool) -> Option<usize> {
        let timeout = deadline.saturating_duration_since(Instant::now());
        let (open, _) = self
            .open_changed
            .wait_timeout_while(self.lock_open(), timeout, |n| !done(*n))
            .unwrap_or_else(|e| e.into_inner());
        done(*open).then_some(*open)
    }

    /// Where each of `devices` is, for [`ServerState::by_addr`].
    pub fn index_devices(devices: &[DeviceSlot]) -> HashMap<(u16, Interface, u16), usize> {
        let mut by_addr = HashMap::new();
        for (i, d) in devices.iter().enumerate() {
            if let Ok(port) = u16::try_from(d.addr.robot) {
                by_addr
                    .entry((port, d.addr.interf, d.addr.index))
                    .or_insert(i);
            }
        }
        by_addr
    }

    pub fn device(&self, port: u16, interf: Interface, index: u16) -> Option<&DeviceSlot> {
        self.by_addr
            .get(&(port, interf, index))
            .map(|&i| &self.devices[i])
    }

    pub fn devices_on(&self, port: u16) -> impl Iterator<Item = &DeviceSlot> {
        self.devices
            .iter()
            .filter(move |d| d.addr.robot == u32::from(port))
    }

    pub fn register(&self, session: &Arc<SessionState>) {
        let mut sessions = self.sessions.lock().expect("sessions");
        let on_port = sessions.entry(session.port).or_default();
        on_port.retain(|s| s.strong_count() > 0);
        on_port.push(Arc::downgrade(session));
    }

    /// Every connection still alive, on any port.
    pub fn all_sessions(&self) -> Vec<Arc<SessionState>> {
        let sessions = self.sessions.lock().expect("sessions");
        sessions
            .values()
            .flatten()
            .filter_map(Weak::upgrade)
            .collect()
    }
}

//! What a running server shares between its sessions and its publisher.

use std::collections::{HashMap, HashSet};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, Weak};

use tokio::sync::Notify;

use super::device::Device;
use super::queue::OutQueue;
use crate::message::Message;
use crate::wire::{DevAddr, Interface};

/// A device and its full address (server host, port, interface, index).
pub(crate) struct DeviceSlot {
    pub addr: DevAddr,
    pub device: Mutex<Box<dyn Device>>,
}

/// One client connection, as the publisher sees it.
pub(crate) struct SessionState {
    pub port: u16,
    pub subscriptions: Mutex<HashSet<(Interface, u16)>>,
    pub queue: Mutex<OutQueue>,
    pub wake_writer: Notify,
    pub closed: AtomicBool,
}

impl SessionState {
    pub fn new(port: u16) -> SessionState {
        SessionState {
            port,
            subscriptions: Mutex::default(),
            queue: Mutex::default(),
            wake_writer: Notify::new(),
            closed: AtomicBool::new(false),
        }
    }

    /// Queues a message and wakes the writer.
    pub fn send(&self, message: Arc<Message>) {
        self.queue.lock().expect("queue").push(message);
        self.wake_writer.notify_one();
    }

    pub fn is_closed(&self) -> bool {
        self.closed.load(Ordering::Acquire)
    }

    pub fn close(&self) {
        self.closed.store(true, Ordering::Release);
        self.wake_writer.notify_one();
    }
}

/// Everything the server knows.
pub(crate) struct ServerState {
    /// The `host` value written into addresses (the server's IPv4 address in memory order).
    pub host: u32,
    pub devices: Vec<DeviceSlot>,
    /// Live connections by port: a robot's data goes to that robot's port only, so publishing
    /// looks at its own port's connections, not at every connection of every robot.
    pub sessions: Mutex<HashMap<u16, Vec<Weak<SessionState>>>>,
}

impl ServerState {
    pub fn device(&self, port: u16, interf: Interface, index: u16) -> Option<&DeviceSlot> {
        self.devices.iter().find(|d| {
            d.addr.robot == u32::from(port) && d.addr.interf == interf && d.addr.index == index
        })
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

    /// The open connections on `port`.
    pub fn sessions_on(&self, port: u16) -> Vec<Arc<SessionState>> {
        let sessions = self.sessions.lock().expect("sessions");
        sessions
            .get(&port)
            .into_iter()
            .flatten()
            .filter_map(Weak::upgrade)
            .filter(|s| !s.is_closed())
            .collect()
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

//! One connection shared by a `Robot` and all its device objects, and the part every device
//! object has in common: its address, its subscription, and which reading it returned last.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use player_proto::body_kind::{BodyKind, DataBody};
use player_proto::client::{Client, ClientOptions, ConnectionState, RequestError, Stamped};
use player_proto::message::Message;
use player_proto::wire::{DevAddr, Interface};
use pyo3::exceptions::{PyKeyError, PyValueError};
use pyo3::prelude::*;

use crate::errors::{ConnectionError, connect_error, request_error};
use crate::waiting::{Wakeup, wait_for};

/// A connected client and the wake-up its robot thread rings.
pub struct Link {
    pub client: Client,
    pub wakeup: Arc<Wakeup>,
    /// `host:port`, for messages.
    pub place: String,
    /// Per device and message subtype, the sequence number of the reading `read` returned
    /// last: kept here, not in a device object, so that `robot.laser(0).read()` in a loop
    /// never returns the same reading twice either.
    returned: Mutex<HashMap<(Interface, u16, u8), u64>>,
}

impl Link {
    /// Connects (GIL released), waiting at most `timeout` for the handshake.
    pub fn connect(
        py: Python<'_>,
        host: &str,
        port: u16,
        timeout: Duration,
        read_only: bool,
    ) -> PyResult<Arc<Link>> {
        let wakeup = Arc::new(Wakeup::default());
        let options = ClientOptions {
            connect_timeout: timeout,
            request_timeout: timeout.max(Duration::from_millis(100)),
            read_only,
            notifier: Some(wakeup.notifier()),
            ..ClientOptions::default()
        };
        let client = py
            .detach(|| Client::connect(host, port, options))
            .map_err(connect_error)?;
        Ok(Arc::new(Link {
            client,
            wakeup,
            place: format!("{host}:{port}"),
            returned: Mutex::new(HashMap::new()),
        }))
    }

    pub fn is_connected(&self) -> bool {
        self.client.state() == ConnectionState::Connected
    }

    /// A `ConnectionError` unless the connection is up now.
    pub fn check_connected(&self) -> PyResult<()> {
        match self.client.state() {
            ConnectionState::Connected => Ok(()),
            state => {
                let why = self
                    .client
                    .last_disconnect()
                    .unwrap_or_else(|| format!("{state:?}"));
                Err(ConnectionError::new_err(format!(
                    "the Player server at {} is not connected ({why}); the client reconnects \
                     by itself and restores its subscriptions",
                    self.place
                )))
            }
        }
    }

    /// The device `interf:index`, subscribed. A negative index is a `ValueError`; a device the
    /// server does not list is a `KeyError` that lists what it has.
    pub fn open(
        self: &Arc<Self>,
        py: Python<'_>,
        interf: Interface,
        index: i64,
    ) -> PyResult<DeviceCore> {
        let name = interf.name().unwrap_or("device");
        let index = u16::try_from(index).map_err(|_| {
            PyValueError::new_err(format!(
                "{name} index must be between 0 and 65535, got {index}"
            ))
        })?;
        let addr = self.client.addr(interf, index);
        let devices = self.client.devices();
        let listed = devices
            .iter()
            .any(|d| d.addr.interf == interf && d.addr.index == index);
        if !listed {
            let have: Vec<String> = devices
                .iter()
                .map(|d| format!("{}:{}", d.addr.interf.name().unwrap_or("?"), d.addr.index))
                .collect();
            return Err(PyKeyError::new_err(format!(
                "{name}:{index} is not on the Player server at {} (it has: {})",
                self.place,
                have.join(", ")
            )));
        }
        let core = DeviceCore {
            link: self.clone(),
            addr,
            label: format!("{name}:{index}"),
        };
        py.detach(|| self.client.subscribe(addr))
            .map_err(|e| core.error(e, "subscribing"))?;
        Ok(core)
    }
}

/// A subscribed device of one connection.
pub struct DeviceCore {
    pub link: Arc<Link>,
    pub addr: DevAddr,
    /// `laser:0`, for messages.
    pub label: String,
}

impl DeviceCore {
    pub fn error(&self, err: RequestError, doing: &str) -> PyErr {
        request_error(err, &format!("{} {doing}", self.label), &self.link.place)
    }

    /// The newest reading whose body is a `T`, if any arrived.
    pub fn newest<T: DataBody>(&self) -> Option<(T, Stamped)> {
        self.link.client.latest_of::<T>(self.addr)
    }

    /// Waits for a reading newer than the one returned last (never the same one twice).
    pub fn next<T: DataBody>(&self, py: Python<'_>, timeout: Duration) -> PyResult<(T, Stamped)> {
        let what = format!("waiting for {} on {}", self.label, self.link.place);
        let key = (self.addr.interf, self.addr.index, T::KIND.subtype());
        let returned = || {
            let map = self.link.returned.lock().unwrap_or_else(|e| e.into_inner());
            map.get(&key).copied().unwrap_or(0)
        };
        let last = returned();
        let found = wait_for(
            py,
            &self.link.wakeup,
            timeout,
            &what,
            || self.newest::<T>().filter(|(_, s)| s.seq > last),
            || self.link.check_connected(),
        )?;
        let mut map = self.link.returned.lock().unwrap_or_else(|e| e.into_inner());
        let seen = map.entry(key).or_insert(0);
        *seen = (*seen).max(found.1.seq);
        Ok(found)
    }

    /// A "get" request (GIL released while waiting for the reply).
    pub fn fetch<T: Clone + Send>(&self, py: Python<'_>, kind: BodyKind<T>) -> PyResult<T> {
        py.detach(|| self.link.client.fetch(self.addr, kind))
            .map_err(|e| self.error(e, "request"))
    }

    /// A "set" request carrying `value`, waiting for the ACK.
    pub fn set<T: Send>(&self, py: Python<'_>, kind: BodyKind<T>, value: T) -> PyResult<Message> {
        py.detach(|| self.link.client.request_with(self.addr, kind, value))
            .map_err(|e| self.error(e, "request"))
    }

    /// Sends a command; a read-only connection refuses it with `PermissionError`.
    pub fn command(&self, body: impl Into<player_proto::message::Body>) -> PyResult<()> {
        self.link
            .client
            .try_command(self.addr, body)
            .map_err(|e| self.error(e, "command"))
    }
}

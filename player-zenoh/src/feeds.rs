//! A robot found in Zenoh costs its site what is looked at here: a device's data is
//! subscribed to in Zenoh only while some local Player client is subscribed to the device,
//! and let go after. The robot's relay publishes a device's data, and subscribes to it
//! upstream, only while a Zenoh subscriber matches its key (its front's matching listener),
//! so one subscription per device looked at, not one to every device of the robot, is what
//! keeps the rest of the robot quiet.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, MutexGuard};

use bytes::Bytes;
use player_front::Device;
use player_proto::message::Body;
use player_proto::server::Publisher;
use player_proto::wire::{DevAddr, HEADER_LEN, Header};
use zenoh::Session;
use zenoh::Wait;
use zenoh::pubsub::Subscriber;

use crate::error::ZenohError;

/// Where the data of a robot's devices goes (its local server, once started) and the Zenoh
/// subscriptions held for it; shared by the robot's devices.
#[derive(Clone, Default)]
pub(crate) struct Feeds(Arc<Mutex<Inner>>);

#[derive(Default)]
struct Inner {
    local: Option<LocalServer>,
    /// Per device: local subscribers now, and the Zenoh subscription held for them.
    data: HashMap<Device, (usize, Subscriber<()>)>,
}

/// The local server the robot is served on.
struct LocalServer {
    publisher: Publisher,
    port: u32,
}

impl Feeds {
    fn lock(&self) -> MutexGuard<'_, Inner> {
        self.0.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// The robot's local server started: data goes to its subscribers from now on.
    pub fn serve_on(&self, publisher: Publisher, port: u16) {
        self.lock().local = Some(LocalServer {
            publisher,
            port: u32::from(port),
        });
    }

    /// A local client subscribed to `device`: the first subscribes to `key` in Zenoh.
    pub fn subscribed(
        &self,
        session: &Session,
        device: Device,
        key: String,
    ) -> Result<(), ZenohError> {
        if let Some((count, _)) = self.lock().data.get_mut(&device) {
            *count += 1;
            return Ok(());
        }
        // Declared with the lock let go: a sample's callback takes it.
        let feeds = self.clone();
        let subscriber = session
            .declare_subscriber(key)
            .callback(move |sample| feeds.publish(&sample.payload().to_bytes()))
            .wait()?;
        self.lock().data.insert(device, (1, subscriber));
        Ok(())
    }

    /// A local client let go of `device`: the last lets go of it in Zenoh.
    pub fn unsubscribed(&self, device: Device) {
        let gone = {
            let mut inner = self.lock();
            match inner.data.get_mut(&device) {
                Some((count, _)) if *count > 1 => {
                    *count -= 1;
                    None
                }
                Some(_) => inner.data.remove(&device),
                None => None,
            }
        };
        // Undeclared with the lock let go: undeclaring may wait for a callback that takes it.
        drop(gone);
    }

    /// Devices subscribed to in Zenoh now.
    pub fn subscriptions(&self) -> usize {
        self.lock().data.len()
    }

    /// The robot is no longer served: its subscriptions let go, its server forgotten.
    pub fn stop(&self) {
        let inner = std::mem::take(&mut *self.lock());
        drop(inner);
    }

    /// One of the robot's data messages (header and body, as its relay put it in Zenoh) to
    /// the local server's subscribers, the bytes untouched.
    fn publish(&self, raw: &[u8]) {
        let Some(Ok(header)) = Header::decode_slice(raw) else {
            return;
        };
        let body = &raw[HEADER_LEN..];
        let body = if body.is_empty() {
            Body::Empty
        } else {
            Body::Unknown(Bytes::copy_from_slice(body))
        };
        let inner = self.lock();
        let Some(local) = &inner.local else {
            return;
        };
        let addr = DevAddr {
            host: 0,
            robot: local.port,
            ..header.addr
        };
        local
            .publisher
            .publish(addr, header.subtype, body, header.timestamp);
    }
}

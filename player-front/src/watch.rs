//! Watching drives subscribing: a front costs what its viewers look at.
//!
//! A robot's server computes and sends a device's data only while someone is subscribed to
//! it; the relay subscribes upstream only while someone looks. Each front is handed, per
//! robot, a [`Watch`]: while a viewer looks at a device (a page showing the robot, a Foxglove
//! client subscribed to one of its channels, a Zenoh subscriber matching its key) the front
//! holds a [`Look`] at it, and drops the look when nobody does. The relay counts the looks of
//! every front (and its Player observers) and subscribes to a device on the first, and
//! unsubscribes on the last.
//!
//! A front that does not say what is looked at answers [`Watching::Everything`] (the
//! default of [`crate::Front::watch`]): every device of the robot is then subscribed for as
//! long as the relay runs, as before watching existed.

use std::fmt;
use std::sync::Arc;

use player_proto::wire::Interface;

/// A device of a robot, as the relay subscribes to it: its interface and index.
pub type Device = (Interface, u16);

/// What the relay does with a front's looks at one robot: counts them, subscribing upstream
/// on a device's first look and unsubscribing on its last. Never blocks (called from the
/// fronts' runtimes and from the robot's own thread).
pub trait Upstream: Send + Sync {
    fn look(&self, device: Device);
    fn look_away(&self, device: Device);
}

/// A front's handle on one robot's upstream subscriptions; cheap to clone.
#[derive(Clone)]
pub struct Watch {
    upstream: Arc<dyn Upstream>,
}

impl Watch {
    pub fn new(upstream: Arc<dyn Upstream>) -> Watch {
        Watch { upstream }
    }

    /// Someone looks at `device` until the returned [`Look`] is dropped.
    pub fn look(&self, device: Device) -> Look {
        self.upstream.look(device);
        Look {
            upstream: self.upstream.clone(),
            device,
        }
    }
}

impl fmt::Debug for Watch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("Watch")
    }
}

/// One look at one device: the relay keeps the device subscribed while any look at it is
/// held, and this one ends when dropped (a page closed, a channel unsubscribed).
pub struct Look {
    upstream: Arc<dyn Upstream>,
    device: Device,
}

impl Look {
    pub fn device(&self) -> Device {
        self.device
    }
}

impl Drop for Look {
    fn drop(&mut self) {
        self.upstream.look_away(self.device);
    }
}

impl fmt::Debug for Look {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Look({}:{})", self.device.0, self.device.1)
    }
}

/// How a front wants a robot subscribed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Watching {
    /// Every device, all the time (a front that does not say what is looked at).
    Everything,
    /// What the front looks at through the robot's [`Watch`], while it does.
    AsLooked,
}

#[cfg(test)]
mod tests {
    use std::sync::Mutex;

    use super::*;

    #[derive(Default)]
    struct Counting(Mutex<Vec<(Device, i32)>>);

    impl Upstream for Counting {
        fn look(&self, device: Device) {
            self.0.lock().unwrap().push((device, 1));
        }
        fn look_away(&self, device: Device) {
            self.0.lock().unwrap().push((device, -1));
        }
    }

    #[test]
    fn a_look_is_counted_when_taken_and_ended_when_dropped() {
        let counting = Arc::new(Counting::default());
        let watch = Watch::new(counting.clone());
        let laser = (Interface::LASER, 0);
        let look = watch.look(laser);
        assert_eq!(*counting.0.lock().unwrap(), [(laser, 1)]);
        drop(look);
        assert_eq!(*counting.0.lock().unwrap(), [(laser, 1), (laser, -1)]);
    }
}

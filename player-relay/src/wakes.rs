//! When a robot's client wakes the relay's thread that follows it. The client calls its
//! notifier on every message it stores: at a thousand robots that is ten thousand thread
//! wake-ups a second, each a context switch, for data only the downstream server's
//! observers need — the fronts hear it on the client's own thread, through the tap. So the
//! follower is woken for data only once an observer has subscribed to one of the robot's
//! devices (observers' subscriptions are kept, and so is this), and always when the
//! connection comes or goes (which starts and stops serving the robot, and its survey).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, OnceLock, Weak};

use player_proto::client::{Client, ConnectionState};

use crate::subscriptions::Subscriptions;

/// Decides, on the robot's thread, whether the follower is worth waking.
pub(crate) struct Wakes {
    client: OnceLock<Weak<Client>>,
    /// Whether the client was connected at the last notification.
    connected: AtomicBool,
    /// The robot's subscriptions, which know whether an observer ever subscribed.
    subscriptions: Arc<Subscriptions>,
}

impl Wakes {
    pub(crate) fn new(subscriptions: Arc<Subscriptions>) -> Wakes {
        Wakes {
            client: OnceLock::new(),
            connected: AtomicBool::new(false),
            subscriptions,
        }
    }

    /// The client whose state is looked at (a weak handle: the client owns its notifier).
    pub(crate) fn set_client(&self, client: &Arc<Client>) {
        let _ = self.client.set(Arc::downgrade(client));
    }

    /// Whether this notification should wake the follower.
    pub(crate) fn wake(&self) -> bool {
        let Some(client) = self.client.get().and_then(Weak::upgrade) else {
            return true;
        };
        let connected = client.state() == ConnectionState::Connected;
        let changed = self.connected.swap(connected, Ordering::Relaxed) != connected;
        changed || self.subscriptions.observed()
    }
}

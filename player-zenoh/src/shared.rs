//! What the Zenoh front's parts share: its configuration, each robot as it knows it, and the
//! state the publishing task, the taps and the Zenoh callbacks (commands, queryables, matching
//! subscribers) all reach. Its own module, below the front and every part it starts.

use std::collections::HashMap;
use std::sync::atomic::AtomicU64;
use std::sync::{Arc, Mutex, MutexGuard};

use player_front::{Device, Look, Watch};
use player_proto::client::Client;
use zenoh::Session;
use zenoh::liveliness::LivelinessToken;

use crate::cache::ReplyCache;
use crate::keys::RobotKey;
use crate::queue::EventQueue;

/// Events waiting for the publishing task, at most: about a second of a busy relay's data.
pub const DEFAULT_QUEUE: usize = 4096;

/// How the front publishes.
#[derive(Debug, Clone)]
pub struct FrontConfig {
    /// The `<site>` of every key.
    pub site: String,
    /// The identity whose commands reach the robots; `None`: nobody's do.
    pub controller: Option<String>,
    /// See [`DEFAULT_QUEUE`].
    pub queue: usize,
}

impl FrontConfig {
    pub fn new(site: &str) -> FrontConfig {
        FrontConfig {
            site: site.into(),
            controller: None,
            queue: DEFAULT_QUEUE,
        }
    }
}

/// One robot, as the front knows it.
#[derive(Default)]
pub(crate) struct RobotEntry {
    /// The relay's upstream client, for commands and requests (see [`ZenohFront::add_robot`]).
    pub client: Option<Arc<Client>>,
    pub cache: ReplyCache,
    pub connected: bool,
    pub token: Option<LivelinessToken>,
    /// The relay's subscriptions to the robot, where it subscribes as Zenoh subscribers
    /// match; `None`: every message is published (a client that subscribes by itself).
    pub watch: Option<Watch>,
}

/// What the publishing task, the taps and the Zenoh callbacks share.
pub(crate) struct FrontShared {
    pub config: FrontConfig,
    pub session: Session,
    pub queue: EventQueue,
    pub robots: Mutex<HashMap<RobotKey, RobotEntry>>,
    /// A look per device whose data key some Zenoh subscriber matches now.
    pub looks: Mutex<HashMap<(RobotKey, Device), Look>>,
    pub runtime: tokio::runtime::Handle,
    /// Commands and requests refused (not the controller, stale, malformed).
    pub refused: AtomicU64,
}

impl FrontShared {
    pub fn robots(&self) -> MutexGuard<'_, HashMap<RobotKey, RobotEntry>> {
        self.robots.lock().unwrap_or_else(|e| e.into_inner())
    }

    pub fn looks(&self) -> MutexGuard<'_, HashMap<(RobotKey, Device), Look>> {
        self.looks.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Whether `device`'s data is published: some subscriber matches its key, or the robot
    /// is not watched (everything is published).
    pub fn looked_at(&self, robot: &RobotKey, device: Device) -> bool {
        let watched = self.robots().get(robot).is_some_and(|r| r.watch.is_some());
        !watched || self.looks().contains_key(&(robot.clone(), device))
    }

    /// A subscriber matches `device`'s data key (`matching`), or none does any more: the
    /// relay is asked to subscribe to it, or let it go.
    pub fn matching(&self, robot: &RobotKey, device: Device, matching: bool) {
        let key = (robot.clone(), device);
        if !matching {
            self.looks().remove(&key);
            return;
        }
        let watch = self.robots().get(robot).and_then(|r| r.watch.clone());
        if let Some(watch) = watch {
            self.looks()
                .entry(key)
                .or_insert_with(|| watch.look(device));
        }
    }

    /// The upstream client of a robot of this front that is connected now.
    pub fn client(&self, robot: &RobotKey) -> Option<Arc<Client>> {
        let robots = self.robots();
        let entry = robots.get(robot)?;
        entry.connected.then(|| entry.client.clone()).flatten()
    }
}

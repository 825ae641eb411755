//! A front: one thing the relay carries its robots to that is not a Player client — the web
//! page, Foxglove, Zenoh, and the next one. The relay drives every front it was given alike:
//!
//! 1. **a robot arrived** — [`Front::arrived`], once per robot, before its connection opens;
//!    the front answers with the robot's tap;
//! 2. **its messages** — the tap hears, on the robot's own thread, each connection open
//!    (`TapEvent::Opened`), every message either way as it crossed the wire (`Frame`);
//! 3. **it left** — the tap hears the connection close (`Closed`, with why); a robot that
//!    comes back opens again on the same tap;
//! 4. **stop** — [`Front::stop`], once, after every robot's thread has ended.
//!
//! A front that passes commands on (the page's controller, Zenoh's) is also handed each
//! robot's upstream client ([`Front::commands_through`]), and every front the robot's
//! [`Watch`] ([`Front::watch`]): what its viewers look at is what the relay subscribes to.

use std::sync::Arc;

use player_proto::RobotId;
use player_proto::client::{Client, ConnectionTap};

use crate::watch::{Watch, Watching};

pub trait Front: Send + Sync {
    /// What the front is called in logs.
    fn name(&self) -> &str;

    /// The relay carries `robot` from now on: the tap that hears its connections and
    /// messages. Called on the relay's thread; the tap is called on the robot's, and must not
    /// block (a slow tap slows the robot).
    fn arrived(&self, robot: &RobotId) -> ConnectionTap;

    /// The relay's upstream client of `robot`, for a front that passes commands on. Nothing
    /// by default.
    fn commands_through(&self, robot: &RobotId, client: Arc<Client>) {
        let _ = (robot, client);
    }

    /// The relay's subscriptions to `robot`, for a front that looks only at what its viewers
    /// do: it answers [`Watching::AsLooked`] and holds a [`crate::watch::Look`] per device
    /// looked at. By default a front watches everything: every device stays subscribed.
    fn watch(&self, robot: &RobotId, watch: Watch) -> Watching {
        let _ = (robot, watch);
        Watching::Everything
    }

    /// The relay stops (its robots' threads have ended): let the viewers go. Nothing by
    /// default; a front also stops when dropped.
    fn stop(&self) {}
}

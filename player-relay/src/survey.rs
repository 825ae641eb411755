//! For the relay's fronts (the web page, a Foxglove server), which are not Player clients and
//! so never subscribe or ask: on each connection to a robot, hold all its devices subscribed
//! for a moment, ask what describes them (geometries, configurations, map tiles) and wait for
//! each one's first data — so that every front knows what the robot has (Foxglove advertises
//! a channel once it has converted a message for it) — then let go of whatever nobody looks
//! at. The answers and the first data reach the fronts through the upstream client's tap, and
//! the fronts keep what describes a device for the viewers that come later.

use std::sync::Arc;
use std::time::{Duration, Instant};

use player_front::Device;
use player_proto::RobotId;
use player_proto::client::Client;
use player_proto::client::describe::describe;

use crate::subscriptions::Subscriptions;

/// How long a robot has to answer the survey's questions.
const SURVEY_WAIT: Duration = Duration::from_secs(5);

/// How long the survey holds a device for its first data: a device with nothing to say yet
/// (a planner with no path) is let go after this.
const FIRST_DATA_WAIT: Duration = Duration::from_secs(2);

/// How often the survey looks whether every device's first data came.
const FIRST_DATA_POLL: Duration = Duration::from_millis(50);

/// Surveys the robot on a thread of its own: the relay's robot thread never waits on it.
pub(crate) fn start(id: &RobotId, upstream: &Arc<Client>, subscriptions: &Arc<Subscriptions>) {
    let (id, upstream, subscriptions) = (id.clone(), upstream.clone(), subscriptions.clone());
    let spawned = std::thread::Builder::new()
        .name(format!("survey {id}"))
        .spawn(move || survey(&id, &upstream, &subscriptions));
    if let Err(e) = spawned {
        tracing::error!("cannot start a survey thread: {e}");
    }
}

fn survey(id: &RobotId, upstream: &Client, subscriptions: &Subscriptions) {
    let devices: Vec<Device> = upstream
        .devices()
        .iter()
        .map(|d| (d.addr.interf, d.addr.index))
        .collect();
    subscriptions.survey(&devices);
    let addrs: Vec<_> = devices
        .iter()
        .map(|&(interf, index)| upstream.addr(interf, index))
        .collect();
    let described = describe(addrs.iter().map(|addr| (upstream, *addr)), SURVEY_WAIT);
    let deadline = Instant::now() + FIRST_DATA_WAIT;
    while Instant::now() < deadline && addrs.iter().any(|addr| upstream.stats(*addr).messages == 0)
    {
        std::thread::sleep(FIRST_DATA_POLL);
    }
    subscriptions.surveyed();
    tracing::debug!(robot = %id, ?described, "surveyed for the fronts");
}

//! For the relay's fronts (the web page, a Foxglove server), which are not Player clients and
//! so never subscribe or ask: on each connection to a robot, subscribe to all its devices and
//! ask what describes them (geometries, configurations, map tiles). The answers reach the
//! fronts through the upstream client's tap, like the data that follows.

use std::sync::Arc;
use std::time::Duration;

use player_proto::RobotId;
use player_proto::client::Client;
use player_proto::client::describe::describe;

use crate::relayed_device::UpstreamSubscriptions;

/// How long a robot has to answer the survey's subscriptions, and then its questions.
const SURVEY_WAIT: Duration = Duration::from_secs(5);

/// Surveys the robot on a thread of its own: the relay's robot thread never waits on it.
pub(crate) fn start(id: &RobotId, upstream: &Arc<Client>, subscribed: &UpstreamSubscriptions) {
    let (id, upstream, subscribed) = (id.clone(), upstream.clone(), subscribed.clone());
    let spawned = std::thread::Builder::new()
        .name(format!("survey {id}"))
        .spawn(move || survey(&id, &upstream, &subscribed));
    if let Err(e) = spawned {
        tracing::error!("cannot start a survey thread: {e}");
    }
}

fn survey(id: &RobotId, upstream: &Client, subscribed: &UpstreamSubscriptions) {
    let mut pending = Vec::new();
    for device in upstream.devices() {
        let addr = upstream.addr(device.addr.interf, device.addr.index);
        let key = (addr.interf, addr.index);
        // A device subscribed once stays subscribed across reconnections (the client restores
        // it): asking again would register the relay twice with a real Player server.
        let first = subscribed
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .insert(key);
        if first {
            pending.push((addr, Some(upstream.subscribe_async(addr))));
        } else {
            pending.push((addr, None));
        }
    }
    let mut devices = Vec::new();
    for (addr, reply) in pending {
        match reply.map(|r| r.wait(SURVEY_WAIT)) {
            Some(Err(e)) => {
                tracing::warn!(device = %addr, "not subscribed for the relay's fronts: {e}");
                subscribed
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .remove(&(addr.interf, addr.index));
            }
            _ => devices.push((upstream, addr)),
        }
    }
    let described = describe(devices, SURVEY_WAIT);
    tracing::debug!(
        robot = %id,
        ?described,
        "surveyed for the fronts"
    );
}

//! The queryables that describe a front's robots from its cache: `…/devices` (the device
//! list, then each driver name, as the Player replies the relay got) and
//! `…/<interface>/<index>/replies` (each cached reply, with the request it answers as the
//! attachment). A bridge asks them when it serves a robot and when a client asks for a
//! device's geometry, so the robot itself is asked once per relay connection, however many
//! bridges and clients there are.

use std::sync::Arc;

use zenoh::Wait;
use zenoh::key_expr::KeyExpr;
use zenoh::query::{Query, Queryable};

use crate::error::ZenohError;
use crate::keys::{Leaf, every_device, every_devices};
use crate::shared::FrontShared;

/// Whether a query asks for `key`.
fn asks_for(query: &Query, key: &str) -> bool {
    KeyExpr::try_from(key).is_ok_and(|key| query.key_expr().intersects(&key))
}

pub(crate) fn declare_devices(shared: &Arc<FrontShared>) -> Result<Queryable<()>, ZenohError> {
    let handler = shared.clone();
    Ok(shared
        .session
        .declare_queryable(every_devices(&shared.config.site))
        .callback(move |query| {
            let answers: Vec<_> = handler
                .robots()
                .iter()
                .filter(|(robot, entry)| {
                    entry.token.is_some() && asks_for(&query, &robot.devices())
                })
                .flat_map(|(robot, entry)| {
                    let key = robot.devices();
                    entry
                        .cache
                        .devices()
                        .into_iter()
                        .map(move |m| (key.clone(), m))
                })
                .collect();
            for (key, message) in answers {
                if let Err(e) = query.reply(key, message).wait() {
                    tracing::debug!("device list not sent: {e}");
                }
            }
        })
        .wait()?)
}

pub(crate) fn declare_replies(shared: &Arc<FrontShared>) -> Result<Queryable<()>, ZenohError> {
    let handler = shared.clone();
    Ok(shared
        .session
        .declare_queryable(every_device(&shared.config.site, Leaf::Replies))
        .callback(move |query| {
            let mut answers = Vec::new();
            for (robot, entry) in handler.robots().iter() {
                if !entry.connected {
                    continue;
                }
                for (interf, index, replies) in entry.cache.devices_described() {
                    let key = robot.device(interf, index, Leaf::Replies);
                    if asks_for(&query, &key) {
                        answers.extend(replies.iter().map(|r| (key.clone(), r.clone())));
                    }
                }
            }
            for (key, cached) in answers {
                let sent = query
                    .reply(key, cached.reply)
                    .attachment(cached.request)
                    .wait();
                if let Err(e) = sent {
                    tracing::debug!("cached reply not sent: {e}");
                }
            }
        })
        .wait()?)
}

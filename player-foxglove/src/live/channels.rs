//! The channels served so far, one per topic, made when its first message comes and never
//! removed (a robot that goes and comes back publishes on the same topics), with what is
//! latched on each.
//!
//! Some messages come once per connection to a robot: a device's geometry (its transform
//! robot → sensor), the map's grid, a body's shape, a planner's path. A viewer that
//! subscribes later would never see them, so the latest of each (per transform child, or per
//! topic) is kept and sent to a viewer when it subscribes. Re-logging them periodically to
//! everyone would also work, but costs every viewer bandwidth forever and leaves a new one
//! waiting up to a period.

use std::collections::{BTreeMap, HashMap};

use axum::extract::ws::Utf8Bytes;
use bytes::Bytes;

use super::wire::{self, ChannelId};
use crate::{FoxgloveMessage, MESSAGE_ENCODING, Output};

pub struct Channel {
    pub topic: String,
    /// The channel as `advertise` lists it (JSON, written once).
    advertised: String,
    /// The newest message of each kind that comes once, by what it describes: encoded,
    /// with its log time.
    latched: HashMap<String, (Bytes, u64)>,
}

#[derive(Default)]
pub struct Channels {
    by_id: BTreeMap<ChannelId, Channel>,
    by_topic: HashMap<String, ChannelId>,
}

impl Channels {
    /// The channel of `output`'s topic, and the `advertise` to send everyone when it is new.
    pub fn channel_of(&mut self, output: &Output) -> (ChannelId, Option<Utf8Bytes>) {
        if let Some(id) = self.by_topic.get(&output.topic) {
            return (*id, None);
        }
        let id = self.by_id.len() as ChannelId + 1;
        let advertised = wire::channel(
            id,
            &output.topic,
            &output.message.schema(),
            MESSAGE_ENCODING,
        );
        let advertise = wire::advertise([advertised.as_str()]);
        self.by_topic.insert(output.topic.clone(), id);
        self.by_id.insert(
            id,
            Channel {
                topic: output.topic.clone(),
                advertised,
                latched: HashMap::new(),
            },
        );
        (id, Some(advertise))
    }

    /// Whether `output` is kept for later subscribers (a message that comes once).
    pub fn latches(output: &Output) -> bool {
        latch_key(output).is_some()
    }

    /// Keeps `payload` for later subscribers if `output` is a message that comes once.
    pub fn latch(&mut self, id: ChannelId, output: &Output, payload: &Bytes, log_time: u64) {
        if let (Some(key), Some(channel)) = (latch_key(output), self.by_id.get_mut(&id)) {
            channel.latched.insert(key, (payload.clone(), log_time));
        }
    }

    /// What a new subscriber to `id` is sent first (nothing for an unknown channel).
    pub fn latched(&self, id: ChannelId) -> impl Iterator<Item = &(Bytes, u64)> {
        self.by_id
            .get(&id)
            .into_iter()
            .flat_map(|channel| channel.latched.values())
    }

    pub fn contains(&self, id: ChannelId) -> bool {
        self.by_id.contains_key(&id)
    }

    /// Every channel in one `advertise`, for a viewer that connects now; `None` when there
    /// is none yet.
    pub fn advertise_all(&self) -> Option<Utf8Bytes> {
        (!self.by_id.is_empty())
            .then(|| wire::advertise(self.by_id.values().map(|c| c.advertised.as_str())))
    }

    pub fn topics(&self) -> impl Iterator<Item = &str> {
        self.by_id.values().map(|c| c.topic.as_str())
    }
}

/// What a message that comes once is kept under, or `None` for one that streams.
fn latch_key(output: &Output) -> Option<String> {
    match &output.message {
        FoxgloveMessage::FrameTransform(t) => Some(t.child_frame_id.clone()),
        FoxgloveMessage::Grid(_) | FoxgloveMessage::SceneUpdate(_) => Some(output.topic.clone()),
        _ => None,
    }
}

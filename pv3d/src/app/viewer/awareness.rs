//! Awareness events from the scene: which tagged objects came and went, and which went into
//! or out of which zone, between one look and the next. Tags are how world entities are
//! known, so an object is followed by its node and named by its name.

use std::collections::{BTreeMap, BTreeSet};

use framework::scene::{NodeId, Scene};
use glam::Vec2;

use crate::composition::Trigger;

/// Something that happened to a tagged object.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AwarenessEvent {
    pub trigger: Trigger,
    /// The object's node (it may be gone: `leave`), and its name.
    pub node: NodeId,
    pub object: String,
    pub tags: Vec<String>,
    /// The zone entered or left (zone events only).
    pub zone: Option<String>,
}

/// A tagged object as last seen.
#[derive(Debug, Clone, PartialEq)]
pub struct Seen {
    pub name: String,
    pub tags: Vec<String>,
    pub at: Vec2,
}

/// What the previous look found.
#[derive(Debug, Default)]
pub struct Watcher {
    objects: BTreeMap<NodeId, Seen>,
    inside: BTreeSet<(NodeId, String)>,
}

/// The objects carrying any of `tags`, and those `watcher` watched that are still in the
/// scene (so that losing a tag is seen as that, not as leaving), by node.
pub fn tagged(scene: &Scene, tags: &BTreeSet<String>, watcher: &Watcher) -> BTreeMap<NodeId, Seen> {
    scene
        .iter()
        .filter(|(id, o)| {
            o.tags.iter().any(|t| tags.contains(t)) || watcher.objects.contains_key(id)
        })
        .map(|(id, o)| {
            let seen = Seen {
                name: o.name.clone(),
                tags: o.tags.clone(),
                at: scene.world_transform(id).translation.truncate(),
            };
            (id, seen)
        })
        .collect()
}

impl Watcher {
    /// Compares this look with the last: `now` the tagged objects, `inside` which of them
    /// are in which zone (empty when nobody asked the zones). An object that left the scene
    /// also leaves its zones.
    pub fn look(
        &mut self,
        now: BTreeMap<NodeId, Seen>,
        inside: BTreeSet<(NodeId, String)>,
    ) -> Vec<AwarenessEvent> {
        let event = |trigger, node: NodeId, seen: &Seen, zone: Option<&String>| AwarenessEvent {
            trigger,
            node,
            object: seen.name.clone(),
            tags: seen.tags.clone(),
            zone: zone.cloned(),
        };
        let mut events = Vec::new();
        let changed = |trigger, node: NodeId, seen: &Seen, tags: Vec<String>| AwarenessEvent {
            trigger,
            node,
            object: seen.name.clone(),
            tags,
            zone: None,
        };
        for (id, seen) in &now {
            match self.objects.get(id) {
                None => {
                    events.push(event(Trigger::Appear, *id, seen, None));
                    events.push(changed(Trigger::Tagged, *id, seen, seen.tags.clone()));
                }
                Some(before) => {
                    let gained = difference(&seen.tags, &before.tags);
                    let lost = difference(&before.tags, &seen.tags);
                    if !gained.is_empty() {
                        events.push(changed(Trigger::Tagged, *id, seen, gained));
                    }
                    if !lost.is_empty() {
                        events.push(changed(Trigger::Untagged, *id, seen, lost));
                    }
                }
            }
        }
        for (node, zone) in inside.difference(&self.inside) {
            if let Some(seen) = now.get(node) {
                events.push(event(Trigger::Enter, *node, seen, Some(zone)));
            }
        }
        for (node, zone) in self.inside.difference(&inside) {
            if let Some(seen) = now.get(node).or_else(|| self.objects.get(node)) {
                events.push(event(Trigger::Exit, *node, seen, Some(zone)));
            }
        }
        for (id, seen) in &self.objects {
            if !now.contains_key(id) {
                events.push(event(Trigger::Leave, *id, seen, None));
            }
        }
        self.objects = now;
        self.inside = inside;
        events
    }
}

/// The tags in `a` that are not in `b`.
fn difference(a: &[String], b: &[String]) -> Vec<String> {
    a.iter().filter(|t| !b.contains(t)).cloned().collect()
}

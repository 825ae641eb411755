//! Running the composition's `<reaction>`s: each update the viewer looks at the tagged
//! objects, asks the zones manager where they are ("which zone" — the same query any
//! component may send), and for each awareness event runs the reactions that wait for it:
//! a query sent, a sentence said, a command carried out, a component loaded.

use std::collections::BTreeSet;

use framework::query::{Query, QueryError, Target, XmlElement};

use super::Viewer;
use super::awareness::{AwarenessEvent, Watcher, tagged};
use crate::composition::{
    Element, FoundDevice, PluginInstance, REACTIONS_LIBRARY, Reaction, ReactionAction, bind_named,
    listed_devices, parse_reactions,
};

/// Who is asked "which zone".
const ZONES: &str = "libpv3d_zones";

/// The reactions of a composition and what they have seen.
#[derive(Debug, Default)]
pub struct Reactions {
    reactions: Vec<Reaction>,
    watcher: Watcher,
    /// Sentences said, oldest first (for the speech component, the panel and tests).
    pub said: Vec<String>,
    /// Events that fired a reaction, oldest first, as "trigger object [zone]".
    pub fired: Vec<String>,
    /// The zones could not be asked (no zones in the composition): said once.
    zones_missing_reported: bool,
}

impl Reactions {
    fn tags(&self) -> BTreeSet<String> {
        self.reactions
            .iter()
            .flat_map(|r| r.tags.iter().cloned())
            .collect()
    }

    fn matching(&self, event: &AwarenessEvent) -> Vec<Reaction> {
        self.reactions
            .iter()
            .filter(|r| r.on == event.trigger)
            .filter(|r| r.tags.is_empty() || r.tags.iter().any(|t| event.tags.contains(t)))
            .filter(|r| r.zone.is_none() || r.zone == event.zone)
            .cloned()
            .collect()
    }
}

impl Viewer {
    /// Takes the `<reaction>`s out of the instances (they are not plugins); a bad one is
    /// reported in [`Viewer::errors`] with where it was written.
    pub(super) fn take_reactions(&mut self, instances: &mut Vec<PluginInstance>) {
        instances.retain(|instance| {
            if instance.library() != REACTIONS_LIBRARY {
                return true;
            }
            match parse_reactions(&instance.element) {
                Ok(mut reactions) => self.reactions.reactions.append(&mut reactions),
                Err(e) => self.errors.push(e.to_string()),
            }
            false
        });
    }

    /// The reactions' record: sentences said and events that fired something.
    pub fn reactions(&self) -> &Reactions {
        &self.reactions
    }

    /// One look at the world, and the reactions its events call for.
    pub(super) fn react(&mut self) {
        if self.reactions.reactions.is_empty() {
            return;
        }
        let now = tagged(&self.scene, &self.reactions.tags(), &self.reactions.watcher);
        let wants_zones = self.reactions.reactions.iter().any(|r| r.on.is_zone());
        let mut inside = BTreeSet::new();
        if wants_zones {
            for (node, seen) in &now {
                let point = XmlElement::new("point")
                    .with_attr("x", seen.at.x)
                    .with_attr("y", seen.at.y);
                let query = Query::new(Target::Named(ZONES.into()), "which zone").with_child(point);
                match self.route_query(&query) {
                    Ok(reply) => inside.extend(
                        reply
                            .body
                            .children
                            .iter()
                            .filter_map(|z| z.attr("name"))
                            .map(|zone| (*node, zone.to_string())),
                    ),
                    Err(e @ QueryError::NoSuchComponent { .. }) => {
                        if !std::mem::replace(&mut self.reactions.zones_missing_reported, true) {
                            tracing::warn!("reactions on zones wait in vain: {e}");
                        }
                        break;
                    }
                    Err(e) => tracing::warn!("reactions: {e}"),
                }
            }
        }
        for event in self.reactions.watcher.look(now, inside) {
            for reaction in self.reactions.matching(&event) {
                self.fire(&reaction, &event);
            }
        }
    }

    fn fire(&mut self, reaction: &Reaction, event: &AwarenessEvent) {
        let what = match &event.zone {
            Some(zone) => format!("{} {} {zone}", event.trigger.name(), event.object),
            None => format!("{} {}", event.trigger.name(), event.object),
        };
        tracing::info!(reaction = %reaction.origin, "reaction to {what}");
        self.reactions.fired.push(what);
        for action in &reaction.actions {
            match action {
                ReactionAction::Query(query) => {
                    // Errors are logged by `ask`; a reaction carries on with its next action.
                    let _ = self.ask(query);
                }
                ReactionAction::Say(sentence) => {
                    tracing::info!("say: {sentence}");
                    // Out loud through the servers' speech devices, when there are any.
                    self.say(sentence);
                    self.reactions.said.push(sentence.clone());
                }
                ReactionAction::Command(sentence) => {
                    // Said and shown by `command` itself, like a typed one.
                    let _ = self.command(sentence);
                }
                ReactionAction::Load(plugin) => self.load(plugin, event),
            }
        }
    }
}

impl Viewer {
    /// A reaction's `<load>`: the plugin is bound, as a composition's would be, to a device
    /// its `<playerDeviceMask>` fits — first among the devices of the robot the event is
    /// about (same server, same index: "the camera of the robot that stalled"), then among
    /// all the servers list. One already running for that device is not loaded twice, and a
    /// mask that nothing fits is reported, not loaded without its device.
    fn load(&mut self, plugin: &Element, event: &AwarenessEvent) {
        let devices = self
            .robots
            .as_ref()
            .map(|robots| listed_devices(robots))
            .unwrap_or_default();
        let near = self
            .owner_of(event.node)
            .and_then(|slot| self.slots[slot].instance.device.clone());
        let of_robot = |d: &&FoundDevice| {
            near.as_ref().is_some_and(|n| {
                n.host == d.host && n.port == d.port && n.addr.index == d.addr.index
            })
        };
        let mine: Vec<FoundDevice> = devices.iter().filter(of_robot).cloned().collect();
        let mut instance = bind_named(plugin, &mine);
        if instance.device.is_none() {
            instance = bind_named(plugin, &devices);
        }
        if instance.waits_for_device() {
            let e = format!(
                "{}: <load> for {}: no device listed now fits its playerDeviceMask; not loaded",
                plugin.pos, event.object
            );
            tracing::warn!("{e}");
            self.errors.push(e);
            return;
        }
        let running = self.slots.iter().any(|slot| {
            slot.instance.library() == instance.library()
                && slot.instance.element.attr("id") == instance.element.attr("id")
                && slot.instance.device == instance.device
        });
        if running {
            tracing::debug!("{}: {} runs already", plugin.pos, instance.id());
            return;
        }
        let robots = self.robots.clone();
        let lookup =
            |device: &framework::config::DeviceRef| robots.as_ref().and_then(|r| r.device(device));
        self.add_plugins(vec![instance], &lookup);
    }
}

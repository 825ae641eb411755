//! Device awareness: a robot's node carries its condition as tags — `stalled` (it pushes
//! against something), `stale` (its data stopped coming), `link down` (its server is lost) —
//! so that reactions (`<reaction on="tagged" tag="stalled">`) and queries see it the way they
//! see a person: by tag.

use std::time::Duration;

use super::Position2dPlugin;
use framework::plugin::PluginContext;

pub const STALLED: &str = "stalled";
pub const STALE: &str = "stale";
pub const LINK_DOWN: &str = "link down";

/// Data older than this is stale: twenty missed samples at Stage's usual 10 Hz.
pub const STALE_AFTER: Duration = Duration::from_secs(2);

impl Position2dPlugin {
    /// Puts the condition tags on the robot's node, touching the scene only when they change.
    pub(super) fn tag_condition(&mut self, ctx: &mut PluginContext<'_>) {
        let stale = self
            .last_data
            .is_some_and(|t| ctx.now.saturating_duration_since(t) > STALE_AFTER);
        let link_down = ctx.device.is_some_and(|d| !d.is_connected());
        let wanted = [
            (STALLED, self.stalled),
            (STALE, stale),
            (LINK_DOWN, link_down),
        ];
        let Some(node) = ctx.scene.get(self.node) else {
            return;
        };
        if wanted.iter().all(|(tag, on)| node.has_tag(tag) == *on) {
            return;
        }
        if let Some(node) = ctx.scene.get_mut(self.node) {
            for (tag, on) in wanted {
                node.tags.retain(|t| t != tag);
                if on {
                    node.tags.push(tag.to_string());
                }
            }
        }
    }
}

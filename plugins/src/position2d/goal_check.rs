//! Before driving to a point, a robot asks the others: the map "is point free", the zones
//! manager "which zone" — and gives the goal up when the point is a wall or lies in a zone it
//! must avoid (`avoidZones`, "keep out" by default, several separated by `|`). Zones are
//! places every robot shares; the robot does not hold a copy of them, it asks. Without a map
//! or zones in the composition, nobody answers and the robot goes.

use glam::Vec2;

use super::Position2dPlugin;
use super::goal::Goal;
use super::zone_guard::ZONES;
use framework::plugin::PluginContext;
use framework::query::{Query, QueryError, Reply, Target, XmlElement};

const MAP: &str = "libpv3d_map";
/// The zones a robot avoids unless told otherwise.
pub const DEFAULT_AVOID_ZONES: &str = "keep out";
/// A reply point this close to the goal is about the goal, m.
const SAME_POINT: f32 = 1e-3;

impl Position2dPlugin {
    /// Asks about the goal point just set (only sent where the viewer routes queries).
    pub(super) fn check_goal(&mut self, ctx: &mut PluginContext<'_>) {
        let Some(Goal::Point(p)) = self.goal else {
            return;
        };
        let point = XmlElement::new("point")
            .with_attr("x", p.x)
            .with_attr("y", p.y);
        let ask = |to: &str, name: &str| {
            Query::new(Target::Named(to.into()), name).with_child(point.clone())
        };
        ctx.send(ask(MAP, "is point free"));
        ctx.send(ask(ZONES, "which zone"));
    }

    /// Gives up the goal when the answer says the point is no place to go.
    pub(super) fn goal_checked(
        &mut self,
        query: &Query,
        result: &Result<Reply, QueryError>,
        ctx: &mut PluginContext<'_>,
    ) {
        let (Ok(reply), Ok((x, y)), Some(Goal::Point(goal))) = (result, query.point(), &self.goal)
        else {
            return;
        };
        if goal.distance(Vec2::new(x as f32, y as f32)) > SAME_POINT {
            return; // An answer about a goal since replaced.
        }
        let why = if query.is("is point free") && reply.body.attr("state") == Some("occupied") {
            Some("the map says it is occupied".to_string())
        } else if query.is("which zone") {
            reply
                .body
                .children
                .iter()
                .filter_map(|z| z.attr("name"))
                .find(|zone| self.zone_guard.avoids(zone))
                .map(|zone| format!("it lies in the zone {zone:?}"))
        } else {
            None
        };
        if let Some(why) = why {
            tracing::warn!("{}: not going to ({x:.2}, {y:.2}): {why}", self.config.id);
            self.stop(ctx);
            self.refused = Some(why);
        }
    }
}

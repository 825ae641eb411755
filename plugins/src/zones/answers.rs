//! What the zones manager answers: "which zone" contains a point (`<point x y/>`) or a tagged
//! object (`robot="robot1"`, any object's name), so that zones are places every component
//! shares — a robot asks before it enters `keep out`, a reaction asks where a person is; and
//! "where is" a zone (`zone="charging"`): the point a robot sent there goes to.

use glam::Vec2;

use framework::plugin::PluginContext;
use framework::query::{BAD_ARGUMENTS, FAILED, Query, Reply, XmlElement};
use framework::scene::polygon::contains;

use super::ZonesPlugin;

impl ZonesPlugin {
    /// Names of the zones containing `point`, in composition order.
    pub fn zones_at(&self, point: Vec2) -> Vec<&str> {
        self.zones
            .iter()
            .filter(|z| contains(&z.corners, point))
            .map(|z| z.name.as_str())
            .collect()
    }

    pub(super) fn answer_query(&self, query: &Query, ctx: &PluginContext<'_>) -> Option<Reply> {
        if query.is("where is") {
            return Some(self.where_is(query));
        }
        if !query.is("which zone") {
            return None;
        }
        let point = match query.argument("robot").or_else(|| query.argument("object")) {
            Some(name) => {
                let found = ctx.scene.iter().find(|(_, o)| o.name == name.trim());
                match found {
                    Some((id, _)) => ctx.scene.world_transform(id).translation.truncate(),
                    None => {
                        return Some(Reply::failed(
                            FAILED,
                            format!("which zone: no object called {name:?} in the scene"),
                        ));
                    }
                }
            }
            None => match query.point() {
                Ok((x, y)) => Vec2::new(x as f32, y as f32),
                Err(e) => {
                    return Some(Reply::failed(
                        BAD_ARGUMENTS,
                        format!("which zone needs robot=\"name\" or <point x y/>: {e}"),
                    ));
                }
            },
        };
        let mut zones = XmlElement::new("zones")
            .with_attr("x", point.x)
            .with_attr("y", point.y);
        for name in self.zones_at(point) {
            zones
                .children
                .push(XmlElement::new("zone").with_attr("name", name));
        }
        Some(Reply::done(zones))
    }
}

impl ZonesPlugin {
    /// `<point x y zone="…"/>` at the named zone's centre.
    fn where_is(&self, query: &Query) -> Reply {
        let Some(name) = query.argument("zone").filter(|z| !z.trim().is_empty()) else {
            return Reply::failed(BAD_ARGUMENTS, "where is needs zone=\"name\"");
        };
        match self.zones.iter().find(|z| z.name == name.trim()) {
            Some(zone) => {
                let centre = zone.centre();
                Reply::done(
                    XmlElement::new("point")
                        .with_attr("x", centre.x)
                        .with_attr("y", centre.y)
                        .with_attr("zone", &zone.name),
                )
            }
            None => {
                let known: Vec<&str> = self.zones.iter().map(|z| z.name.as_str()).collect();
                Reply::failed(
                    FAILED,
                    format!(
                        "no zone called {:?}; zones: {}",
                        name.trim(),
                        known.join(", ")
                    ),
                )
            }
        }
    }
}

//! What the world itself answers, from the scene alone: "is there any person?". Tags are how
//! world entities are known, so any component can ask about any kind of thing without
//! knowing which component put it there.

use glam::Vec3;

use super::{BAD_ARGUMENTS, Query, Reply, XmlElement};
use crate::scene::Scene;

/// The name a query is addressed to for the world's own answers (`to="world"`).
pub const WORLD: &str = "world";

/// Answers "is there any" (argument `tag`, or the query's text after the name) with
/// `<objects count="N">` listing each tagged object's name and position, or `None` when the
/// query is not one the world knows. A count of 0 is still a reply with error 0: the
/// question was answered, and the answer is "no".
pub fn answer_world(query: &Query, scene: &Scene) -> Option<Reply> {
    if !query.is("is there any") {
        return None;
    }
    let Some(tag) = query.argument("tag").filter(|t| !t.trim().is_empty()) else {
        return Some(Reply::failed(
            BAD_ARGUMENTS,
            "\"is there any\" needs a tag argument (tag=\"person\")",
        ));
    };
    let mut objects = XmlElement::new("objects").with_attr("tag", &tag);
    for (id, object) in scene.iter().filter(|(_, o)| o.has_tag(tag.trim())) {
        let at = Vec3::from(scene.world_transform(id).translation);
        objects.children.push(
            XmlElement::new("object")
                .with_attr("name", &object.name)
                .with_attr("x", at.x)
                .with_attr("y", at.y),
        );
    }
    let count = objects.children.len();
    Some(Reply::done(objects.with_attr("count", count)))
}

//! What the map answers: "is point free" — whether a robot could stand at a point, as the
//! map knows it (free, occupied, unknown, or off the map), so that a component can check a
//! goal before sending a robot there.

use framework::query::{BAD_ARGUMENTS, FAILED, Query, Reply, XmlElement};

use super::MapPlugin;
use super::grid::{FREE_GREY, OCCUPIED_GREY};

impl MapPlugin {
    pub(super) fn answer_query(&self, query: &Query) -> Option<Reply> {
        if !query.is("is point free") {
            return None;
        }
        let (x, y) = match query.point() {
            Ok(p) => p,
            Err(e) => {
                let message = format!("is point free needs <point x y/>: {e}");
                return Some(Reply::failed(BAD_ARGUMENTS, message));
            }
        };
        let Some(grid) = self.fetch.grid() else {
            return Some(Reply::failed(FAILED, "the map has not arrived yet"));
        };
        let state = match grid.grey_at(x as f32, y as f32) {
            None => "outside",
            Some(FREE_GREY) => "free",
            Some(OCCUPIED_GREY) => "occupied",
            Some(_) => "unknown",
        };
        let body = XmlElement::new("cell")
            .with_attr("x", x)
            .with_attr("y", y)
            .with_attr("state", state)
            .with_attr("free", state == "free");
        // "No" is an answer too: error 0, so the query stops here rather than going on to
        // another map.
        Some(Reply::done(body))
    }
}

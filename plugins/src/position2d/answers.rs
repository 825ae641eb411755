//! What a robot answers when other components (a reaction, a script, the command line, another
//! robot) ask it: "go to" a point or an object, "follow" an object, "stop", and "where are
//! you". The same goals the person sets by clicking, so a query and a click drive the robot
//! the same way — a point goes to the robot's planner when one drives it.
//!
//! An object is named by `object="name"` (a robot, any scene object) or by `tag="person"`
//! (the one carrying the tag nearest to the robot); a point by `<point x y/>`.

use glam::Vec2;

use super::Position2dPlugin;
use super::actions::{FOLLOW, GO_TO};
use super::goal::Goal;
use framework::action::ObjectRef;
use framework::plugin::PluginContext;
use framework::query::{BAD_ARGUMENTS, FAILED, Query, Reply, XmlElement};

impl Position2dPlugin {
    pub(super) fn answer_query(
        &mut self,
        query: &Query,
        ctx: &mut PluginContext<'_>,
    ) -> Option<Reply> {
        let name = query.name.trim().to_ascii_lowercase();
        Some(match name.as_str() {
            "where are you" => Reply::done(self.whereabouts()),
            "stop" => {
                self.stop(ctx);
                Reply::done(self.whereabouts())
            }
            "go to" if names_object(query) => self.act_on_object(GO_TO, query, ctx),
            "go to" => match query.point() {
                Ok((x, y)) => {
                    let point = Vec2::new(x as f32, y as f32);
                    // A robot with a planner is driven by it, as a click would have it.
                    let planned = self.goal_to_planner(point, ctx);
                    if !planned {
                        self.set_goal(Goal::Point(point), ctx);
                    }
                    Reply::done(self.whereabouts().with_attr("planner", planned))
                }
                Err(e) => Reply::failed(
                    BAD_ARGUMENTS,
                    format!("go to needs <point x y/>, object=\"name\" or tag=\"tag\": {e}"),
                ),
            },
            "follow" if names_object(query) => self.act_on_object(FOLLOW, query, ctx),
            "follow" => Reply::failed(
                BAD_ARGUMENTS,
                "follow needs object=\"name\" or tag=\"tag\" (tag=\"person\")",
            ),
            _ => return None,
        })
    }

    /// Runs `action` on the object the query names, replying with what is being done.
    fn act_on_object(&mut self, action: &str, query: &Query, ctx: &mut PluginContext<'_>) -> Reply {
        let target = match self.object_named_by(query, ctx) {
            Ok(target) => target,
            Err(why) => return Reply::failed(FAILED, format!("{}: {why}", self.config.id)),
        };
        let doing = if action == FOLLOW {
            "following"
        } else {
            "going to"
        };
        let reply = XmlElement::new(doing)
            .with_attr("name", &target.name)
            .with_attr("x", target.position.x)
            .with_attr("y", target.position.y);
        self.act(action, &target, ctx);
        Reply::done(reply)
    }

    /// The object `object="name"` names, or the nearest one carrying `tag="…"`; never the
    /// robot itself.
    fn object_named_by(
        &self,
        query: &Query,
        ctx: &PluginContext<'_>,
    ) -> Result<ObjectRef, NotInScene> {
        let robot = Vec2::new(self.pose.0, self.pose.1);
        let wanted = |o: &framework::scene::Object3D| match query.argument("object") {
            Some(name) => o.name == name.trim(),
            None => query.argument("tag").is_some_and(|t| o.has_tag(t.trim())),
        };
        ctx.scene
            .iter()
            .filter(|(id, o)| *id != self.node && wanted(o))
            .filter_map(|(id, _)| ObjectRef::of(ctx.scene, id))
            .min_by(|a, b| {
                let d = |o: &ObjectRef| o.position.truncate().distance(robot);
                d(a).total_cmp(&d(b))
            })
            .ok_or_else(|| match query.argument("object") {
                Some(name) => NotInScene::Named(name.trim().to_string()),
                None => {
                    NotInScene::Tagged(query.argument("tag").unwrap_or_default().trim().to_string())
                }
            })
    }

    fn whereabouts(&self) -> XmlElement {
        let (x, y, a) = self.pose;
        let mut at = XmlElement::new("pose")
            .with_attr("x", x)
            .with_attr("y", y)
            .with_attr("a", a)
            .with_attr("stalled", self.stalled);
        if let Some(goal) = &self.goal {
            at.children.push(match goal {
                Goal::Point(p) => XmlElement::new("goal")
                    .with_attr("x", p.x)
                    .with_attr("y", p.y),
                Goal::Follow { target, .. } => {
                    XmlElement::new("following").with_attr("name", &target.name)
                }
            });
        }
        if let Some(zone) = self.zone_guard.blocked_by() {
            at.children
                .push(XmlElement::new("waiting").with_attr("zone", zone));
        }
        at
    }
}

/// Whether the query names an object (by name or tag) rather than a point.
fn names_object(query: &Query) -> bool {
    ["object", "tag"]
        .iter()
        .any(|a| query.argument(a).is_some_and(|v| !v.trim().is_empty()))
}

/// Why a query's object is not there to go to or follow.
#[derive(Debug, thiserror::Error)]
enum NotInScene {
    #[error("nothing called {0:?} in the scene")]
    Named(String),
    #[error("nothing tagged {0:?} in the scene")]
    Tagged(String),
}

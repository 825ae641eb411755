//! What a robot answers when other components (a reaction, a script, another robot) ask it:
//! "go to" a point, "follow" a tagged object, "stop", and "where are you". The same goals the
//! person sets by clicking, so a query and a click drive the robot the same way.

use glam::Vec2;

use super::Position2dPlugin;
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
            "go to" => match query.point() {
                Ok((x, y)) => {
                    self.set_goal(Goal::Point(Vec2::new(x as f32, y as f32)), ctx);
                    Reply::done(self.whereabouts())
                }
                Err(e) => Reply::failed(BAD_ARGUMENTS, format!("go to needs <point x y/>: {e}")),
            },
            "follow" => self.follow_tagged(query, ctx),
            _ => return None,
        })
    }

    /// Follows the object with the `tag` argument nearest to the robot.
    fn follow_tagged(&mut self, query: &Query, ctx: &mut PluginContext<'_>) -> Reply {
        let Some(tag) = query.argument("tag").filter(|t| !t.trim().is_empty()) else {
            return Reply::failed(
                BAD_ARGUMENTS,
                "follow needs a tag argument (tag=\"person\")",
            );
        };
        let robot = Vec2::new(self.pose.0, self.pose.1);
        let nearest = ctx
            .scene
            .iter()
            .filter(|(id, o)| *id != self.node && o.has_tag(tag.trim()))
            .filter_map(|(id, _)| ObjectRef::of(ctx.scene, id))
            .min_by(|a, b| {
                let d = |o: &ObjectRef| o.position.truncate().distance(robot);
                d(a).total_cmp(&d(b))
            });
        match nearest {
            Some(target) => {
                let last_seen = target.position.truncate();
                let reply = XmlElement::new("following").with_attr("name", &target.name);
                self.set_goal(Goal::Follow { target, last_seen }, ctx);
                Reply::done(reply)
            }
            None => Reply::failed(
                FAILED,
                format!("{}: nothing tagged {tag:?} to follow", self.config.id),
            ),
        }
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
        at
    }
}

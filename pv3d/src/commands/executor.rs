//! Carrying out a [`Command`] as queries ([`framework::query`]): a zone is asked of the zones
//! manager ("where is"), and each robot is sent "go to", "follow" or "stop", addressed to its
//! id — the very queries a reaction, a script or another component sends. The executor knows
//! the queries, not the plugins that answer them: any component answering "go to" can be
//! commanded in words.

use framework::query::{Query, QueryError, Reply, Target, XmlElement};
use glam::Vec2;

use super::command::{Command, Object, Robots, Verb};

/// Who is asked where a zone is.
pub const ZONES: &str = "libpv3d_zones";

/// Why a parsed command could not be carried out.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExecuteError {
    #[error("no robot named {0} can be driven now")]
    NoSuchRobot(String),
    #[error("a robot cannot follow a place; say \"go to\"")]
    FollowPlace,
    #[error("{0} cannot {1} itself")]
    Itself(String, &'static str),
    #[error("the viewer only observes (--observe): it commands no robot")]
    Observing,
    #[error("there is no robot to command")]
    NoRobots,
    /// A query the command became got no reply with error 0; it names the query and who.
    #[error(transparent)]
    Query(#[from] QueryError),
    #[error("the zones manager's answer to \"where is\" {0:?} has no point: {1}")]
    BadAnswer(String, framework::query::ArgumentError),
}

/// What the executor needs from the viewer: its robots, and its post office.
pub trait CommandTarget {
    /// The robots that can be driven, by name (their plugin ids).
    fn drivable_robots(&self) -> Vec<String>;
    /// Routes `query` to the components it is addressed to.
    fn ask(&mut self, query: &Query) -> Result<Reply, QueryError>;
    fn observing(&self) -> bool;
}

/// Carries out `command`; the reply says what was done, in words.
pub fn execute(target: &mut dyn CommandTarget, command: &Command) -> Result<String, ExecuteError> {
    if target.observing() {
        return Err(ExecuteError::Observing);
    }
    let drivable = target.drivable_robots();
    let robots = match &command.robots {
        Robots::All => drivable.clone(),
        Robots::Named(names) => names.clone(),
    };
    if robots.is_empty() {
        return Err(ExecuteError::NoRobots);
    }
    if let Some(unknown) = robots.iter().find(|r| !drivable.contains(r)) {
        return Err(ExecuteError::NoSuchRobot(unknown.clone()));
    }
    let who = match &command.robots {
        Robots::All => "all robots".to_string(),
        Robots::Named(names) => names.join(" and "),
    };
    let to = |robot: &str| Target::Named(robot.to_string());
    let Some(object) = &command.object else {
        for robot in &robots {
            target.ask(&Query::new(to(robot), "stop"))?;
        }
        return Ok(format!("{who}: stopping"));
    };
    let (name, doing) = match command.verb {
        Verb::Follow => ("follow", "follow"),
        _ => ("go to", "go to"),
    };
    for robot in &robots {
        if matches!(object, Object::Robot(r) if r == robot) {
            return Err(ExecuteError::Itself(robot.clone(), doing));
        }
    }
    let argument = match object {
        Object::Zone(_) | Object::Point(_) if command.verb == Verb::Follow => {
            return Err(ExecuteError::FollowPlace);
        }
        // A place is gone to itself; an object is gone up to (the robot stops short).
        Object::Zone(zone) => Argument::Point(where_is(target, zone)?),
        Object::Point(p) => Argument::Point(*p),
        Object::Robot(r) => Argument::Attr("object", r.clone()),
        Object::Tag(t) => Argument::Attr("tag", t.clone()),
    };
    for robot in &robots {
        let query = Query::new(to(robot), name);
        let query = match &argument {
            Argument::Point(p) => query.with_child(
                XmlElement::new("point")
                    .with_attr("x", p.x)
                    .with_attr("y", p.y),
            ),
            Argument::Attr(key, value) => query.with_attr(key, value),
        };
        target.ask(&query)?;
    }
    let what = match object {
        Object::Zone(z) => format!("zone {z}"),
        Object::Robot(r) => r.clone(),
        Object::Tag(t) => format!("the {t}"),
        Object::Point(p) => format!("({:.2}, {:.2})", p.x, p.y),
    };
    let going = if command.verb == Verb::Follow {
        "following"
    } else {
        "going to"
    };
    Ok(format!("{who}: {going} {what}"))
}

/// How a query names what it acts on.
enum Argument {
    Point(Vec2),
    Attr(&'static str, String),
}

/// The point a robot sent to `zone` goes to, as the zones manager says.
fn where_is(target: &mut dyn CommandTarget, zone: &str) -> Result<Vec2, ExecuteError> {
    let query = Query::new(Target::Named(ZONES.into()), "where is").with_attr("zone", zone);
    let reply = target.ask(&query)?;
    let point = |attr: &str| reply.body.number(attr);
    match (point("x"), point("y")) {
        (Ok(x), Ok(y)) => Ok(Vec2::new(x as f32, y as f32)),
        (Err(e), _) | (_, Err(e)) => Err(ExecuteError::BadAnswer(zone.to_string(), e)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Robots r0 and r1, a zone "dock" at (3, 2); every query is recorded and answered.
    #[derive(Default)]
    struct Post {
        asked: Vec<String>,
    }

    impl CommandTarget for Post {
        fn drivable_robots(&self) -> Vec<String> {
            vec!["r0".into(), "r1".into()]
        }
        fn ask(&mut self, query: &Query) -> Result<Reply, QueryError> {
            self.asked.push(query.to_xml());
            if query.is("where is") {
                return match query.argument("zone").as_deref() {
                    Some("dock") => Ok(Reply::done(
                        XmlElement::new("point").with_attr("x", 3).with_attr("y", 2),
                    )),
                    _ => Err(QueryError::Refused {
                        name: query.name.clone(),
                        to: query.to.clone(),
                        who: ZONES.into(),
                        reply: Box::new(Reply::failed(-1, "no zone called \"attic\"")),
                    }),
                };
            }
            Ok(Reply::done(XmlElement::new("ok")))
        }
        fn observing(&self) -> bool {
            false
        }
    }

    fn command(robots: &[&str], verb: Verb, object: Option<Object>) -> Command {
        Command {
            robots: match robots {
                [] => Robots::All,
                names => Robots::Named(names.iter().map(|s| s.to_string()).collect()),
            },
            verb,
            object,
        }
    }

    #[test]
    fn a_zone_is_asked_of_the_zones_manager_and_each_robot_sent_there() {
        let mut post = Post::default();
        let go = command(&[], Verb::GoTo, Some(Object::Zone("dock".into())));
        assert_eq!(
            execute(&mut post, &go).unwrap(),
            "all robots: going to zone dock"
        );
        assert_eq!(post.asked.len(), 3, "{:?}", post.asked);
        assert!(post.asked[0].contains(r#"to="libpv3d_zones" name="where is""#));
        for (asked, robot) in post.asked[1..].iter().zip(["r0", "r1"]) {
            assert!(
                asked.contains(&format!(r#"to="{robot}" name="go to""#)),
                "{asked}"
            );
            assert!(asked.contains(r#"<point x="3" y="2"/>"#), "{asked}");
        }
    }

    #[test]
    fn objects_are_named_to_the_robot_and_stop_asks_each() {
        let mut post = Post::default();
        let follow = command(&["r1"], Verb::Follow, Some(Object::Tag("person".into())));
        assert_eq!(
            execute(&mut post, &follow).unwrap(),
            "r1: following the person"
        );
        assert!(
            post.asked[0].contains(r#"name="follow" tag="person""#),
            "{:?}",
            post.asked
        );
        let stop = command(&["r0", "r1"], Verb::Stop, None);
        assert_eq!(execute(&mut post, &stop).unwrap(), "r0 and r1: stopping");
        assert_eq!(post.asked.len(), 3);
    }

    #[test]
    fn what_cannot_be_done_says_why() {
        let mut post = Post::default();
        let attic = command(&["r0"], Verb::GoTo, Some(Object::Zone("attic".into())));
        let e = execute(&mut post, &attic).unwrap_err().to_string();
        assert!(e.contains("where is") && e.contains("attic"), "{e}");
        let place = command(&["r0"], Verb::Follow, Some(Object::Point(Vec2::ONE)));
        assert_eq!(execute(&mut post, &place), Err(ExecuteError::FollowPlace));
        let itself = command(&["r0"], Verb::Follow, Some(Object::Robot("r0".into())));
        assert!(matches!(
            execute(&mut post, &itself),
            Err(ExecuteError::Itself(..))
        ));
        let ghost = command(&["r7"], Verb::Stop, None);
        assert_eq!(
            execute(&mut post, &ghost),
            Err(ExecuteError::NoSuchRobot("r7".into()))
        );
    }
}

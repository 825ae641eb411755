//! Carrying out a [`Command`] through the plugin API: "go to" and "follow" become a robot
//! plugin's "Go to" / "Follow" actions on the object, "stop" its stop event. This is the one
//! place that knows how; when components answer queries, this file is what changes.

use framework::action::ObjectRef;
use framework::scene::{NodeId, Scene};
use glam::Vec3;

use super::command::{Command, Object, Robots, Verb};
use super::vocabulary::{ROBOT_TAG, ZONE_TAG_PREFIX};

/// The robot plugin actions a command is carried out with (position2d's names).
pub const GO_TO_ACTION: &str = "Go to";
pub const FOLLOW_ACTION: &str = "Follow";

/// Why a parsed command could not be carried out.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ExecuteError {
    #[error("no robot named {0} can be driven now")]
    NoSuchRobot(String),
    #[error("nothing in the scene is {0} now")]
    NothingThere(String),
    #[error("a robot cannot follow a point; say \"go to\"")]
    FollowPoint,
    #[error("{0} cannot {1} itself")]
    Itself(String, &'static str),
    #[error("the viewer only observes (--observe): it commands no robot")]
    Observing,
    #[error("there is no robot to command")]
    NoRobots,
}

/// What the executor needs from the viewer: its scene and its robots, by name.
pub trait CommandTarget {
    fn scene(&self) -> &Scene;
    /// The robots that can be driven, by name.
    fn drivable_robots(&self) -> Vec<String>;
    /// Runs one of a robot's actions on `target`; false if the robot is not there.
    fn robot_action(&mut self, robot: &str, action: &str, target: &ObjectRef) -> bool;
    /// Sends a robot to a point on the ground, as a click there does when it is selected;
    /// false if the robot is not there.
    fn robot_to_point(&mut self, robot: &str, point: Vec3) -> bool;
    /// Stops one robot; false if it is not there.
    fn stop_robot(&mut self, robot: &str) -> bool;
    fn observing(&self) -> bool;
}

/// Carries out `command`; the reply says what was done, in words.
pub fn execute(target: &mut dyn CommandTarget, command: &Command) -> Result<String, ExecuteError> {
    if target.observing() {
        return Err(ExecuteError::Observing);
    }
    let robots = match &command.robots {
        Robots::All => target.drivable_robots(),
        Robots::Named(names) => names.clone(),
    };
    if robots.is_empty() {
        return Err(ExecuteError::NoRobots);
    }
    let who = match &command.robots {
        Robots::All => "all robots".to_string(),
        Robots::Named(names) => names.join(" and "),
    };
    let Some(object) = &command.object else {
        for robot in &robots {
            if !target.stop_robot(robot) {
                return Err(ExecuteError::NoSuchRobot(robot.clone()));
            }
        }
        return Ok(format!("{who}: stopping"));
    };
    let (action, doing) = match command.verb {
        Verb::Follow if matches!(object, Object::Point(_)) => {
            return Err(ExecuteError::FollowPoint);
        }
        Verb::Follow => (FOLLOW_ACTION, "follow"),
        _ => (GO_TO_ACTION, "go to"),
    };
    for robot in &robots {
        if matches!(object, Object::Robot(r) if r == robot) {
            return Err(ExecuteError::Itself(robot.clone(), doing));
        }
    }
    for robot in &robots {
        let reference = object_ref(target.scene(), object, robot)?;
        // A place is gone to itself; an object is gone up to (its "Go to" stops short).
        let place = matches!(object, Object::Zone(_) | Object::Point(_));
        let sent = if place && command.verb == Verb::GoTo {
            target.robot_to_point(robot, reference.position)
        } else {
            target.robot_action(robot, action, &reference)
        };
        if !sent {
            return Err(ExecuteError::NoSuchRobot(robot.clone()));
        }
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

/// The object as a robot's action takes it. A zone is aimed at by its centre (where its
/// label is drawn); a tag by the object carrying it nearest to the robot.
fn object_ref(scene: &Scene, object: &Object, robot: &str) -> Result<ObjectRef, ExecuteError> {
    let robot_node = find(scene, |o| o.has_tag(ROBOT_TAG) && o.name == robot)
        .ok_or_else(|| ExecuteError::NoSuchRobot(robot.to_string()))?;
    let robot_at = Vec3::from(scene.world_transform(robot_node).translation);
    let node = match object {
        Object::Point(p) => {
            // A point is no object: the robot's own node carries it, only its position counts.
            let mut reference = ObjectRef::of(scene, robot_node)
                .ok_or_else(|| ExecuteError::NoSuchRobot(robot.to_string()))?;
            reference.name = format!("point ({:.2}, {:.2})", p.x, p.y);
            reference.tags = vec!["point".into()];
            reference.position = p.extend(0.0);
            return Ok(reference);
        }
        Object::Zone(zone) => {
            let tag = format!("{ZONE_TAG_PREFIX}{zone}");
            let node = find(scene, |o| o.has_tag(&tag))
                .ok_or_else(|| ExecuteError::NothingThere(format!("zone {zone}")))?;
            let mut reference = ObjectRef::of(scene, node)
                .ok_or_else(|| ExecuteError::NothingThere(format!("zone {zone}")))?;
            if let Some(label) = scene.get(node).and_then(|o| o.geometry.labels.first()) {
                let world = scene.world_transform(node);
                reference.position = world.transform_point3(label.pos);
            }
            return Ok(reference);
        }
        Object::Robot(other) => find(scene, |o| o.has_tag(ROBOT_TAG) && o.name == *other)
            .ok_or_else(|| ExecuteError::NoSuchRobot(other.clone()))?,
        Object::Tag(tag) => scene
            .iter()
            .filter(|(_, o)| o.has_tag(tag))
            .map(|(id, _)| (id, Vec3::from(scene.world_transform(id).translation)))
            .min_by(|a, b| a.1.distance(robot_at).total_cmp(&b.1.distance(robot_at)))
            .map(|(id, _)| id)
            .ok_or_else(|| ExecuteError::NothingThere(format!("tagged {tag}")))?,
    };
    ObjectRef::of(scene, node).ok_or_else(|| ExecuteError::NothingThere(format!("{object:?}")))
}

fn find(scene: &Scene, wanted: impl Fn(&framework::scene::Object3D) -> bool) -> Option<NodeId> {
    scene.iter().find(|(_, o)| wanted(o)).map(|(id, _)| id)
}

//! How a ground click on a selected robot reaches the planner that drives it, through the
//! scene both plugins share (plugins see no other plugin).
//!
//! The rule that pairs them: a planner drives the robot body standing nearest the pose the
//! planner itself reports (`player_planner_data_t.pos`, the robot's pose in the map frame),
//! within [`SAME_ROBOT`]. It needs no parameter, follows the robot wherever the composition
//! puts it, and holds where the map frame is the scene's world frame and odometry starts at
//! the robot's true pose (Stage's default, and player-sim's). The planner tags its node with
//! the robot it drives; the robot, clicked on the ground while selected, leaves a goal
//! request (a child node at the clicked point) under that planner's node, which the planner
//! takes and sends on its next run.

use glam::{Vec2, Vec3};

use framework::scene::{NodeId, Object3D, Scene};

/// How far the planner's reported pose may be from a robot body for it to drive that robot,
/// m: wider than a step's motion, narrower than two robots standing apart.
pub const SAME_ROBOT: f32 = 0.5;
const DRIVES: &str = "drives:";
const GOAL_REQUEST: &str = "planner goal request";

fn drives_tag(robot: NodeId) -> String {
    format!("{DRIVES}{robot:?}")
}

fn ground(scene: &Scene, node: NodeId) -> Vec2 {
    scene.world_transform(node).translation.truncate()
}

/// The robot body nearest `at` within [`SAME_ROBOT`], if any.
pub fn robot_at(scene: &Scene, at: Vec2) -> Option<NodeId> {
    scene
        .iter()
        .filter(|(_, o)| o.has_tag("robot"))
        .map(|(id, _)| (id, ground(scene, id).distance(at)))
        .filter(|&(_, d)| d <= SAME_ROBOT)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(id, _)| id)
}

/// Marks `planner` as driving `robot` (or nothing), replacing what it claimed before.
pub fn claim(scene: &mut Scene, planner: NodeId, robot: Option<NodeId>) {
    let Some(object) = scene.get_mut(planner) else {
        return;
    };
    object.tags.retain(|t| !t.starts_with(DRIVES));
    object.tags.extend(robot.map(drives_tag));
}

/// The planner that drives `robot`, if one claims it.
pub fn planner_of(scene: &Scene, robot: NodeId) -> Option<NodeId> {
    let tag = drives_tag(robot);
    scene
        .iter()
        .find(|(_, o)| o.has_tag(&tag))
        .map(|(id, _)| id)
}

/// Leaves a goal at `point` for `planner` to send.
pub fn request_goal(scene: &mut Scene, planner: NodeId, point: Vec2) {
    let mut request = Object3D::new(GOAL_REQUEST);
    request.parent = Some(planner);
    request.visible = false;
    request.tags.push(GOAL_REQUEST.into());
    request.transform = glam::Affine3A::from_translation(point.extend(0.0));
    scene.add(request);
}

/// The newest goal left for `planner`, taking every request out of the scene.
pub fn take_goal(scene: &mut Scene, planner: NodeId) -> Option<Vec2> {
    let mut requests: Vec<(NodeId, Vec3)> = scene
        .iter()
        .filter(|(_, o)| o.parent == Some(planner) && o.has_tag(GOAL_REQUEST))
        .map(|(id, o)| (id, Vec3::from(o.transform.translation)))
        .collect();
    requests.sort_by_key(|r| r.0);
    for (id, _) in &requests {
        scene.remove(*id);
    }
    requests.last().map(|(_, at)| at.truncate())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn robot(scene: &mut Scene, at: Vec2) -> NodeId {
        let mut body = Object3D::new("robot");
        body.tags.push("robot".into());
        body.transform = glam::Affine3A::from_translation(at.extend(0.0));
        scene.add(body)
    }

    #[test]
    fn the_planner_claims_the_robot_it_reports_and_takes_its_newest_goal() {
        let mut scene = Scene::new();
        let near = robot(&mut scene, Vec2::new(1.0, 1.0));
        let far = robot(&mut scene, Vec2::new(4.0, 1.0));
        let planner = scene.add(Object3D::new("planner"));
        assert_eq!(robot_at(&scene, Vec2::new(1.2, 0.9)), Some(near));
        assert_eq!(robot_at(&scene, Vec2::new(2.5, 1.0)), None);

        let reported = robot_at(&scene, Vec2::new(1.2, 0.9));
        claim(&mut scene, planner, reported);
        assert_eq!(planner_of(&scene, near), Some(planner));
        assert_eq!(planner_of(&scene, far), None);
        claim(&mut scene, planner, Some(far));
        assert_eq!(planner_of(&scene, near), None, "one robot at a time");

        assert_eq!(take_goal(&mut scene, planner), None);
        request_goal(&mut scene, planner, Vec2::new(3.0, 2.0));
        request_goal(&mut scene, planner, Vec2::new(-1.0, 0.5));
        let before = scene.len();
        assert_eq!(take_goal(&mut scene, planner), Some(Vec2::new(-1.0, 0.5)));
        assert_eq!(scene.len(), before - 2, "the requests are gone");
        assert_eq!(take_goal(&mut scene, planner), None);
    }
}

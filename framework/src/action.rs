//! Actions on objects: what the active event handler offers when the person clicks a tagged
//! object ("Go to", "Follow"), and the reference to that object it keeps.
//!
//! The flow: the viewer makes an [`ObjectRef`] of the clicked node and asks the active plugin
//! for [`Plugin::actions_on`](crate::plugin::Plugin::actions_on); a non-empty list becomes a
//! popup, and the person's choice comes back through
//! [`Plugin::run_action`](crate::plugin::Plugin::run_action) with the same reference.
//!
//! Many objects are re-created whenever their data arrives (a fiducial finder rebuilds its
//! markers on every scan), so a plugin that acts on an object over time ("Follow") must not
//! hold on to the [`NodeId`]: [`ObjectRef::locate`] finds the object again by its identity
//! (its `id:N` tag, or its name).

use glam::Vec3;

use crate::scene::{NodeId, Scene};

/// A clicked object, as a plugin may keep it.
#[derive(Debug, Clone, PartialEq)]
pub struct ObjectRef {
    /// The node clicked; may be gone by the next frame.
    pub node: NodeId,
    pub name: String,
    pub tags: Vec<String>,
    /// Where the object was in the world when it was clicked.
    pub position: Vec3,
}

/// An action a plugin offers on an object.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Action {
    /// The name shown in the popup and given back to `run_action`.
    pub name: &'static str,
    /// Shown when the pointer rests on it.
    pub description: String,
}

impl ObjectRef {
    /// A reference to `node` as it is now, or `None` if the scene has no such node.
    pub fn of(scene: &Scene, node: NodeId) -> Option<ObjectRef> {
        let object = scene.get(node)?;
        Some(ObjectRef {
            node,
            name: object.name.clone(),
            tags: object.tags.clone(),
            position: scene.world_transform(node).translation.into(),
        })
    }

    /// The tag that tells this object apart from others of its kind (`id:7`), if any.
    pub fn identity_tag(&self) -> Option<&str> {
        self.tags
            .iter()
            .map(String::as_str)
            .find(|t| t.starts_with("id:"))
    }

    /// A short description for popups: the name and the tags.
    pub fn describe(&self) -> String {
        if self.tags.is_empty() {
            self.name.clone()
        } else {
            format!("{} ({})", self.name, self.tags.join(", "))
        }
    }

    /// Where the object is now: the same node while it lives under the same name, otherwise
    /// the object with the same identity (its `id:N` tag, else its name) nearest to `near`
    /// (two robots' finders may both see marker 7). `None` when nothing matches: the object
    /// is out of sight.
    pub fn locate(&self, scene: &Scene, near: Vec3) -> Option<(NodeId, Vec3)> {
        let at = |id: NodeId| Vec3::from(scene.world_transform(id).translation);
        if scene.get(self.node).is_some_and(|o| o.name == self.name) {
            return Some((self.node, at(self.node)));
        }
        let same = |tags: &[String], name: &str| match self.identity_tag() {
            Some(identity) => tags.iter().any(|t| t == identity),
            None => name == self.name,
        };
        scene
            .iter()
            .filter(|(_, o)| same(&o.tags, &o.name))
            .map(|(id, _)| (id, at(id)))
            .min_by(|a, b| a.1.distance(near).total_cmp(&b.1.distance(near)))
    }
}

impl ObjectRef {
    /// The object that took this one's place once it is lost: the nearest to `near`, within
    /// `within` m, of the same kind (carrying all of its tags that are no identity — `person`,
    /// `fiducial`). A tracker that loses a walker for a scan numbers them anew when it finds
    /// them again (`person 2` comes back as `person 3`); a follower should go on following.
    /// Only tracked objects (with an identity tag) have successors: a robot is one robot.
    pub fn successor(&self, scene: &Scene, near: Vec3, within: f32) -> Option<ObjectRef> {
        self.identity_tag()?;
        let kind: Vec<&String> = self.tags.iter().filter(|t| !t.contains(':')).collect();
        if kind.is_empty() {
            return None;
        }
        scene
            .iter()
            .filter(|(_, o)| kind.iter().all(|k| o.tags.contains(k)))
            .map(|(id, _)| (id, Vec3::from(scene.world_transform(id).translation)))
            .filter(|(_, at)| at.distance(near) <= within)
            .min_by(|a, b| a.1.distance(near).total_cmp(&b.1.distance(near)))
            .and_then(|(id, _)| ObjectRef::of(scene, id))
    }
}

#[cfg(test)]
mod tests {
    use glam::Affine3A;

    use super::*;
    use crate::scene::Object3D;

    fn marker(scene: &mut Scene, id: i32, x: f32) -> NodeId {
        let mut o = Object3D::new(format!("marker {id}"));
        o.tags = vec!["fiducial".into(), format!("id:{id}"), "person".into()];
        o.transform = Affine3A::from_translation(Vec3::new(x, 1.0, 0.0));
        scene.add(o)
    }

    #[test]
    fn a_lost_object_is_succeeded_by_the_nearest_of_its_kind_within_reach() {
        let mut scene = Scene::new();
        let person = |scene: &mut Scene, name: &str, x: f32| {
            let mut o = Object3D::new(name);
            o.tags = vec!["person".into(), format!("id:{name}")];
            o.transform = Affine3A::from_translation(Vec3::new(x, 0.0, 0.0));
            scene.add(o)
        };
        let lost = person(&mut scene, "p2", 0.0);
        let followed = ObjectRef::of(&scene, lost).unwrap();
        scene.remove(lost);
        person(&mut scene, "p3", 0.7);
        person(&mut scene, "p4", 3.0);
        let next = followed.successor(&scene, Vec3::ZERO, 1.5).unwrap();
        assert_eq!(next.name, "p3");
        assert!(
            followed
                .successor(&scene, Vec3::new(9.0, 0.0, 0.0), 1.5)
                .is_none()
        );
        let nameless = ObjectRef {
            tags: vec!["id:p2".into()],
            ..followed
        };
        assert!(
            nameless.successor(&scene, Vec3::ZERO, 1.5).is_none(),
            "no kind"
        );
        let untracked = ObjectRef {
            tags: vec!["person".into()],
            ..nameless
        };
        assert!(
            untracked.successor(&scene, Vec3::ZERO, 1.5).is_none(),
            "no identity"
        );
    }

    #[test]
    fn a_re_created_marker_is_found_again_by_its_id() {
        let mut scene = Scene::new();
        let first = marker(&mut scene, 7, 2.0);
        let other = marker(&mut scene, 8, 2.1);
        let target = ObjectRef::of(&scene, first).unwrap();
        assert_eq!(target.identity_tag(), Some("id:7"));
        assert_eq!(target.locate(&scene, Vec3::ZERO).unwrap().0, first);

        // The next scan: every marker re-created, marker 7 moved on.
        scene.remove(first);
        scene.remove(other);
        marker(&mut scene, 8, 2.0);
        let moved = marker(&mut scene, 7, 3.0);
        let (id, at) = target.locate(&scene, target.position).unwrap();
        assert_eq!(id, moved);
        assert!((at - Vec3::new(3.0, 1.0, 0.0)).length() < 1e-6);

        // Out of sight.
        scene.remove(moved);
        assert!(target.locate(&scene, target.position).is_none());
    }

    #[test]
    fn of_two_sightings_the_nearer_one_is_taken() {
        let mut scene = Scene::new();
        let seen = marker(&mut scene, 7, 0.0);
        let target = ObjectRef::of(&scene, seen).unwrap();
        scene.remove(seen);
        let far = marker(&mut scene, 7, 9.0);
        let near = marker(&mut scene, 7, 0.3);
        assert_eq!(target.locate(&scene, Vec3::ZERO).unwrap().0, near);
        assert_eq!(
            target.locate(&scene, Vec3::new(9.0, 1.0, 0.0)).unwrap().0,
            far
        );
    }
}

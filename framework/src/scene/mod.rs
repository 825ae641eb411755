//! The scene plugins fill and the viewer draws: a tree of [`Object3D`] nodes, each with a
//! transform relative to its parent, tags, optional pick bounds, and [`Geometry`].
//!
//! Plugins own their nodes and rewrite their geometry when new data arrives; the scene counts
//! changes ([`Scene::generation`]) so the viewer redraws only when something changed.

pub mod filter;
pub mod filter_config;
pub mod filtered_picture;
mod geometry;
pub mod image;
pub mod polygon;
pub mod pose;
pub mod virtual_view;

use std::collections::BTreeMap;

use glam::{Affine3A, Vec3};

pub use filter::{FilterChain, GlslKernel, Kernel};
pub use filtered_picture::FilteredPicture;
pub use geometry::{Fan, Geometry, Label, MeshVertex, Rgba, Vertex};
pub use image::{Facing, ImageError, ImageQuad, PixelFormat, Pixels, Sampling};
pub use virtual_view::{ViewError, ViewOutput, VirtualView};

/// A node's identity, stable for its lifetime.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct NodeId(u64);

/// An axis-aligned box in a node's own frame, used for picking.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

impl Aabb {
    /// A box of full size `size` centred on `centre`.
    pub fn centred(centre: Vec3, size: Vec3) -> Aabb {
        Aabb {
            min: centre - size / 2.0,
            max: centre + size / 2.0,
        }
    }
}

/// A thing in the world: a robot body, a laser scan, a fiducial marker, the ground.
#[derive(Debug, Clone, PartialEq)]
pub struct Object3D {
    pub name: String,
    pub parent: Option<NodeId>,
    /// Pose relative to the parent (or the world).
    pub transform: Affine3A,
    /// Free-form tags (`robot`, `fiducial`, `id:7`, `person`) for awareness and picking.
    pub tags: Vec<String>,
    /// Where a click selects this object; `None` = not pickable.
    pub pick_bounds: Option<Aabb>,
    pub visible: bool,
    pub geometry: Geometry,
}

impl Object3D {
    pub fn new(name: impl Into<String>) -> Object3D {
        Object3D {
            name: name.into(),
            parent: None,
            transform: Affine3A::IDENTITY,
            tags: Vec::new(),
            pick_bounds: None,
            visible: true,
            geometry: Geometry::default(),
        }
    }

    pub fn has_tag(&self, tag: &str) -> bool {
        self.tags.iter().any(|t| t == tag)
    }
}

/// How the scene is lit and what is behind it; set by the lights plugin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SceneLighting {
    /// Direction towards the light, world frame.
    pub direction: Vec3,
    /// 0–1: how bright faces turned away from the light are.
    pub ambient: f32,
    pub background: Rgba,
}

impl Default for SceneLighting {
    fn default() -> Self {
        SceneLighting {
            direction: Vec3::new(0.4, -0.3, 1.0),
            ambient: 0.35,
            background: Rgba::rgb(28, 31, 36),
        }
    }
}

/// All objects of a window.
#[derive(Debug, Default)]
pub struct Scene {
    objects: BTreeMap<NodeId, Object3D>,
    next_id: u64,
    generation: u64,
    lighting: SceneLighting,
}

impl Scene {
    pub fn new() -> Scene {
        Scene::default()
    }

    pub fn add(&mut self, object: Object3D) -> NodeId {
        let id = NodeId(self.next_id);
        self.next_id += 1;
        self.objects.insert(id, object);
        self.generation += 1;
        id
    }

    /// Removes an object and every object below it.
    pub fn remove(&mut self, id: NodeId) {
        let children: Vec<NodeId> = self
            .objects
            .iter()
            .filter(|(_, o)| o.parent == Some(id))
            .map(|(&c, _)| c)
            .collect();
        for child in children {
            self.remove(child);
        }
        if self.objects.remove(&id).is_some() {
            self.generation += 1;
        }
    }

    pub fn get(&self, id: NodeId) -> Option<&Object3D> {
        self.objects.get(&id)
    }

    /// Mutable access; counts as a change.
    pub fn get_mut(&mut self, id: NodeId) -> Option<&mut Object3D> {
        self.generation += 1;
        self.objects.get_mut(&id)
    }

    pub fn iter(&self) -> impl Iterator<Item = (NodeId, &Object3D)> {
        self.objects.iter().map(|(&id, o)| (id, o))
    }

    pub fn len(&self) -> usize {
        self.objects.len()
    }

    pub fn is_empty(&self) -> bool {
        self.objects.is_empty()
    }

    pub fn lighting(&self) -> SceneLighting {
        self.lighting
    }

    pub fn set_lighting(&mut self, lighting: SceneLighting) {
        self.lighting = lighting;
        self.generation += 1;
    }

    /// Increases whenever anything in the scene may have changed.
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// The object's pose in the world: its transform composed with its ancestors'. A parent
    /// loop (which `add` cannot create, but a plugin could by editing `parent`) stops the walk.
    pub fn world_transform(&self, id: NodeId) -> Affine3A {
        let mut transform = Affine3A::IDENTITY;
        let mut current = Some(id);
        let mut steps = 0;
        while let Some(node) = current.and_then(|c| self.objects.get(&c)) {
            transform = node.transform * transform;
            current = node.parent;
            steps += 1;
            if steps > self.objects.len() {
                tracing::warn!(name = %node.name, "scene parent loop; drawing it at the loop's pose");
                break;
            }
        }
        transform
    }

    /// Is the object and every ancestor visible?
    pub fn is_shown(&self, id: NodeId) -> bool {
        let mut current = Some(id);
        let mut steps = 0;
        while let Some(node) = current.and_then(|c| self.objects.get(&c)) {
            if !node.visible {
                return false;
            }
            current = node.parent;
            steps += 1;
            if steps > self.objects.len() {
                break;
            }
        }
        true
    }

    /// The nearest pickable object hit by a ray (origin, direction in world space), with the
    /// distance along the ray.
    pub fn pick(&self, origin: Vec3, direction: Vec3) -> Option<(NodeId, f32)> {
        self.objects
            .iter()
            .filter(|&(&id, _)| self.is_shown(id))
            .filter_map(|(&id, o)| {
                let bounds = o.pick_bounds?;
                let to_local = self.world_transform(id).inverse();
                let local_origin = to_local.transform_point3(origin);
                let local_dir = to_local.transform_vector3(direction);
                ray_box(local_origin, local_dir, bounds).map(|t| (id, t))
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }
}

/// Distance along the ray to the box (slab method); `None` if it misses or lies behind.
fn ray_box(origin: Vec3, dir: Vec3, b: Aabb) -> Option<f32> {
    let inv = dir.recip();
    let t1 = (b.min - origin) * inv;
    let t2 = (b.max - origin) * inv;
    let near = t1.min(t2).max_element();
    let far = t1.max(t2).min_element();
    (far >= near.max(0.0)).then_some(near.max(0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn children_move_with_their_parent() {
        let mut scene = Scene::new();
        let mut robot = Object3D::new("robot");
        robot.transform = Affine3A::from_translation(Vec3::new(2.0, 0.0, 0.0));
        let robot = scene.add(robot);
        let mut laser = Object3D::new("laser");
        laser.parent = Some(robot);
        laser.transform = Affine3A::from_translation(Vec3::new(0.1, 0.0, 0.3));
        let laser = scene.add(laser);
        let p = scene.world_transform(laser).transform_point3(Vec3::ZERO);
        assert!((p - Vec3::new(2.1, 0.0, 0.3)).length() < 1e-6);

        scene.remove(robot);
        assert!(scene.get(laser).is_none(), "children go with their parent");
    }

    #[test]
    fn picking_finds_the_nearest_box() {
        let mut scene = Scene::new();
        for (name, x) in [("far", 5.0), ("near", 2.0)] {
            let mut o = Object3D::new(name);
            o.transform = Affine3A::from_translation(Vec3::new(x, 0.0, 0.0));
            o.pick_bounds = Some(Aabb::centred(Vec3::ZERO, Vec3::splat(0.5)));
            scene.add(o);
        }
        let (id, t) = scene.pick(Vec3::ZERO, Vec3::X).unwrap();
        assert_eq!(scene.get(id).unwrap().name, "near");
        assert!((t - 1.75).abs() < 1e-5);
        assert!(scene.pick(Vec3::ZERO, Vec3::Y).is_none());
    }
}

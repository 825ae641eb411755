//! How the view frames the world before the person moves it: deterministically, from what does
//! not depend on which data came first — the ground's floorplan walls, the map, and where the
//! robots stand — and again on every pass while robots arrive, the map
//! comes in or the window settles its size, until the person pans, orbits or zooms.
//!
//! Framing once on whatever was drawn first made the same composition open at two zooms: a
//! laser fan drawn before the ground widened the view, and egui's first pass gives the view
//! another width than the settled window has.

use glam::Vec3;

use crate::render::OrbitCamera;
use framework::scene::{NodeId, Object3D, Scene};

/// Tags of what bounds the world: the ground plugin's walls (its floorplan) and a map.
const WORLD_TAGS: [&str; 2] = ["ground", "map"];
/// The tag of a robot's body.
const ROBOT_TAG: &str = "robot";
/// Room kept round a robot standing at the edge, m: its body and a little floor.
const ROBOT_MARGIN: f32 = 1.0;
/// The smallest extent framed, m: one robot alone is shown with room around it.
const MIN_EXTENT: f32 = 4.0;
/// Margin round the framed bounds, as a fraction.
const MARGIN: f32 = 0.08;

/// What the view frames, in world coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Target {
    pub lo: Vec3,
    pub hi: Vec3,
    pub kind: TargetKind,
}

/// Where a [`Target`]'s bounds come from, most telling first.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TargetKind {
    /// The ground's walls and the map: the world itself.
    World,
    /// No world is drawn: this many robots, where they stand.
    Robots(usize),
    /// Neither: everything drawn but the grid.
    Content,
}

impl Target {
    fn contains(&self, other: &Target) -> bool {
        self.lo.x <= other.lo.x
            && self.lo.y <= other.lo.y
            && self.hi.x >= other.hi.x
            && self.hi.y >= other.hi.y
    }
}

/// The camera's framing of the scene while the person has not moved it.
#[derive(Debug, Default)]
pub struct Framing {
    /// The person (or a program) moved the view: it is theirs from then on.
    user_moved: bool,
    /// What was framed last, for a view of which aspect.
    framed: Option<(Target, f32)>,
    /// The camera's centre and distance as framing left them: anything else moved it.
    left_at: Option<(Vec3, f32)>,
}

impl Framing {
    /// The person moved the view, or began to work in it: never frame again.
    pub fn user_moved(&mut self) {
        self.user_moved = true;
    }

    /// Whether the view still follows the world's bounds.
    pub fn is_automatic(&self) -> bool {
        !self.user_moved
    }

    /// Frames `camera` on `scene` for a view of `aspect` (width / height) when what is to be
    /// framed changed — the world appeared or grew (a map came in), a robot arrived or stepped
    /// out of view, the view's shape changed — unless the camera was moved by anyone else.
    /// Cheap enough for every pass: robots are counted by position, not geometry, and the
    /// world's bounds come from a few objects.
    pub fn update(&mut self, camera: &mut OrbitCamera, scene: &Scene, aspect: f32) {
        if self
            .left_at
            .is_some_and(|at| at != (camera.centre, camera.distance))
        {
            self.user_moved = true;
        }
        if self.user_moved {
            return;
        }
        let Some(target) = framing_target(scene) else {
            return;
        };
        let changed = match self.framed {
            None => true,
            Some((last, last_aspect)) => {
                (aspect - last_aspect).abs() > 1e-3
                    || match (last.kind, target.kind) {
                        (TargetKind::World, TargetKind::World) => last != target,
                        (TargetKind::Robots(n), TargetKind::Robots(m)) if n == m => {
                            !last.contains(&target)
                        }
                        (TargetKind::Content, TargetKind::Content) => !last.contains(&target),
                        _ => true,
                    }
            }
        };
        if changed {
            frame(camera, target.lo, target.hi, aspect);
            self.framed = Some((target, aspect));
            self.left_at = Some((camera.centre, camera.distance));
        }
    }
}

/// What the view frames, in world x–y: the ground's walls and the map when there are any;
/// else every robot where it stands; else everything drawn but the grid.
pub fn framing_target(scene: &Scene) -> Option<Target> {
    let mut world: Option<(Vec3, Vec3)> = None;
    let mut robots: Option<(Vec3, Vec3)> = None;
    let mut robot_count = 0;
    for (id, object) in scene.iter() {
        if !scene.is_shown(id) {
            continue;
        }
        if WORLD_TAGS.iter().any(|tag| object.has_tag(tag)) {
            for p in solid_points(scene, id, object) {
                grow(&mut world, p);
            }
        } else if object.has_tag(ROBOT_TAG) {
            robot_count += 1;
            let at = scene.world_transform(id).transform_point3(Vec3::ZERO);
            let margin = Vec3::new(ROBOT_MARGIN, ROBOT_MARGIN, 0.0);
            grow(&mut robots, at - margin);
            grow(&mut robots, at + margin);
        }
    }
    let target = |(lo, hi): (Vec3, Vec3), kind| Target { lo, hi, kind };
    world
        .map(|b| target(b, TargetKind::World))
        .or_else(|| robots.map(|b| target(b, TargetKind::Robots(robot_count))))
        .or_else(|| content_bounds(scene).map(|b| target(b, TargetKind::Content)))
}

/// The corners of everything drawn solid but the grid.
fn content_bounds(scene: &Scene) -> Option<(Vec3, Vec3)> {
    let mut bounds = None;
    for (id, object) in scene.iter() {
        if object.has_tag("grid") || !scene.is_shown(id) {
            continue;
        }
        for p in solid_points(scene, id, object) {
            grow(&mut bounds, p);
        }
    }
    bounds
}

/// Where `object` draws solid things — meshes, lines and outlines, points, pictures — in world
/// coordinates. Not its flat fills: the ground's plane is a backdrop of any size, while its
/// walls (mesh) and a map's picture are the world.
fn solid_points<'a>(
    scene: &Scene,
    id: NodeId,
    object: &'a Object3D,
) -> impl Iterator<Item = Vec3> + 'a {
    let to_world = scene.world_transform(id);
    let g = &object.geometry;
    let outlines = (g.fans.iter())
        .filter(|f| f.outline.is_some())
        .flat_map(|f| std::iter::once(f.centre).chain(f.rim.iter().copied()));
    g.lines
        .iter()
        .chain(&g.points)
        .map(|v| v.pos)
        .chain(outlines)
        .chain(g.mesh.iter().map(|v| v.pos))
        .chain(g.images.iter().flat_map(|i| i.corners().map(|(p, _)| p)))
        .map(move |p| to_world.transform_point3(p))
}

fn grow(bounds: &mut Option<(Vec3, Vec3)>, p: Vec3) {
    *bounds = Some(match *bounds {
        None => (p, p),
        Some((lo, hi)) => (lo.min(p), hi.max(p)),
    });
}

/// Centres `camera` on `lo`–`hi` and sets its distance so that all of it shows in a view of
/// `aspect`, in either projection.
fn frame(camera: &mut OrbitCamera, lo: Vec3, hi: Vec3, aspect: f32) {
    let extent = (hi - lo).truncate().max(glam::Vec2::splat(MIN_EXTENT));
    let half = (extent.y / 2.0).max(extent.x / 2.0 / aspect.max(0.1)) * (1.0 + MARGIN);
    camera.centre = Vec3::new((lo.x + hi.x) / 2.0, (lo.y + hi.y) / 2.0, 0.0);
    camera.distance = half / (camera.fov_y / 2.0).tan();
}

#[cfg(test)]
mod tests {
    use super::*;
    use framework::scene::{Object3D, Rgba};
    use glam::{Affine3A, Vec2};

    fn walls(scene: &mut Scene, centre: Vec2, size: Vec2) {
        let mut ground = Object3D::new("ground");
        // The plane, far larger than the world: a backdrop, not framed.
        ground.geometry.triangle(
            Vec3::new(-50.0, -50.0, 0.0),
            Vec3::new(50.0, -50.0, 0.0),
            Vec3::new(0.0, 50.0, 0.0),
            Rgba::rgb(50, 50, 50),
        );
        ground.geometry.cuboid(
            centre.extend(0.25),
            size.extend(0.5),
            Rgba::rgb(150, 150, 150),
        );
        ground.tags.push("ground".into());
        scene.add(ground);
    }

    fn robot(scene: &mut Scene, at: Vec2) {
        let mut body = Object3D::new("robot");
        body.tags.push("robot".into());
        body.transform = Affine3A::from_translation(at.extend(0.0));
        body.geometry
            .cuboid(Vec3::ZERO, Vec3::splat(0.4), Rgba::rgb(0, 0, 255));
        scene.add(body);
    }

    fn laser_fan(scene: &mut Scene, reach: f32) {
        let mut fan = Object3D::new("laser");
        fan.geometry
            .point(Vec3::new(reach, 0.0, 0.0), Rgba::rgb(255, 0, 0));
        scene.add(fan);
    }

    fn framed(scene: &Scene, aspect: f32) -> OrbitCamera {
        let mut camera = OrbitCamera::default();
        Framing::default().update(&mut camera, scene, aspect);
        camera
    }

    #[test]
    fn the_world_is_framed_whatever_data_came_first() {
        let mut first = Scene::new();
        walls(&mut first, Vec2::new(8.0, 6.0), Vec2::new(16.0, 12.0));
        robot(&mut first, Vec2::new(3.0, 3.0));
        let mut later = Scene::new();
        walls(&mut later, Vec2::new(8.0, 6.0), Vec2::new(16.0, 12.0));
        robot(&mut later, Vec2::new(3.0, 3.0));
        // A scan reaching out of the world arrived before the picture was framed.
        laser_fan(&mut later, 30.0);
        assert_eq!(framed(&first, 1.6), framed(&later, 1.6));
        let camera = framed(&first, 1.6);
        assert!((camera.centre - Vec3::new(8.0, 6.0, 0.0)).length() < 1e-4);
    }

    #[test]
    fn the_whole_world_shows_at_any_aspect() {
        let mut scene = Scene::new();
        walls(&mut scene, Vec2::ZERO, Vec2::new(20.0, 10.0));
        for aspect in [0.5, 1.0, 2.0, 3.0] {
            let camera = framed(&scene, aspect);
            let half_height = camera.distance * (camera.fov_y / 2.0).tan();
            assert!(half_height >= 5.0, "{aspect}: the height fits");
            assert!(half_height * aspect >= 10.0, "{aspect}: the width fits");
            assert!(
                half_height.min(half_height * aspect) <= 10.0 * (1.0 + MARGIN) + 1e-3,
                "{aspect}: and is not zoomed out further than needed"
            );
        }
    }

    #[test]
    fn robots_that_arrive_are_framed_until_the_person_moves_the_view() {
        let mut scene = Scene::new();
        robot(&mut scene, Vec2::ZERO);
        let mut camera = OrbitCamera::default();
        let mut framing = Framing::default();
        framing.update(&mut camera, &scene, 1.0);
        let before = camera.clone();
        // A second robot arrives far away: the view grows to hold both.
        robot(&mut scene, Vec2::new(20.0, 0.0));
        framing.update(&mut camera, &scene, 1.0);
        assert!(camera.centre.x > before.centre.x && camera.distance > before.distance);
        // The window settles its size: framed again for the new shape.
        let square = camera.clone();
        framing.update(&mut camera, &scene, 2.0);
        assert!(
            camera.distance < square.distance,
            "a wider view needs less height"
        );
        // Once the person zoomed, the view is theirs.
        framing.user_moved();
        camera.zoom(0.5);
        let theirs = camera.clone();
        robot(&mut scene, Vec2::new(-30.0, 0.0));
        framing.update(&mut camera, &scene, 1.0);
        assert_eq!(camera, theirs);
        assert!(!framing.is_automatic());
    }

    #[test]
    fn a_camera_set_by_a_program_is_left_where_it_was_set() {
        let mut scene = Scene::new();
        walls(&mut scene, Vec2::ZERO, Vec2::new(10.0, 10.0));
        let mut camera = OrbitCamera::default();
        let mut framing = Framing::default();
        framing.update(&mut camera, &scene, 1.0);
        camera.centre = Vec3::new(3.0, 3.0, 0.0);
        camera.distance = 2.0;
        let set = camera.clone();
        framing.update(&mut camera, &scene, 1.5);
        assert_eq!(camera, set);
        assert!(!framing.is_automatic());
    }

    #[test]
    fn robots_driving_inside_the_world_do_not_move_the_view() {
        let mut scene = Scene::new();
        walls(&mut scene, Vec2::ZERO, Vec2::new(10.0, 10.0));
        robot(&mut scene, Vec2::new(4.5, 0.0));
        let camera = framed(&scene, 1.0);
        let mut other = Scene::new();
        walls(&mut other, Vec2::ZERO, Vec2::new(10.0, 10.0));
        robot(&mut other, Vec2::new(-4.5, 3.0));
        assert_eq!(
            framed(&other, 1.0),
            camera,
            "the world, not where its robots are"
        );
    }

    #[test]
    fn robots_alone_are_framed_with_room_and_nothing_at_all_leaves_the_camera() {
        let mut scene = Scene::new();
        let untouched = framed(&scene, 1.0);
        assert_eq!(untouched, OrbitCamera::default(), "nothing to frame");
        robot(&mut scene, Vec2::new(2.0, 1.0));
        let camera = framed(&scene, 1.0);
        assert!((camera.centre - Vec3::new(2.0, 1.0, 0.0)).length() < 1e-4);
        let half_height = camera.distance * (camera.fov_y / 2.0).tan();
        assert!(half_height >= MIN_EXTENT / 2.0, "{half_height}");
    }
}

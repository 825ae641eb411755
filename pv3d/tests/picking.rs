//! Picking in both camera modes: the ray under the pointer, as the 3D view casts it, finds the
//! object drawn under the pointer — in the top view and in the perspective view after orbiting
//! — and nothing beside it.

use framework::scene::{Aabb, Object3D, Scene};
use glam::{Affine3A, Vec2, Vec3};
use pv3d::render::OrbitCamera;

fn ndc(pixel: Vec2, size: Vec2) -> Vec2 {
    Vec2::new(pixel.x / size.x * 2.0 - 1.0, 1.0 - pixel.y / size.y * 2.0)
}

#[test]
fn the_object_under_the_pointer_is_picked_in_both_projections() {
    let mut scene = Scene::new();
    let mut robot = Object3D::new("robot");
    robot.transform = Affine3A::from_translation(Vec3::new(2.0, 1.0, 0.0));
    robot.pick_bounds = Some(Aabb::centred(
        Vec3::new(0.0, 0.0, 0.2),
        Vec3::new(0.5, 0.4, 0.4),
    ));
    let robot = scene.add(robot);
    let mut marker = Object3D::new("marker");
    marker.transform = Affine3A::from_translation(Vec3::new(-3.0, 2.0, 0.0));
    marker.pick_bounds = Some(Aabb::centred(Vec3::new(0.0, 0.0, 0.15), Vec3::splat(0.3)));
    let marker = scene.add(marker);

    let size = Vec2::new(800.0, 600.0);
    let aspect = size.x / size.y;
    let mut camera = OrbitCamera {
        distance: 15.0,
        ..OrbitCamera::default()
    };
    for view in ["top", "perspective", "perspective, orbited"] {
        match view {
            "perspective" => camera.toggle_projection(),
            "perspective, orbited" => camera.orbit(0.9, -0.3),
            _ => {}
        }
        for (node, at) in [
            (robot, Vec3::new(2.0, 1.0, 0.2)),
            (marker, Vec3::new(-3.0, 2.0, 0.15)),
        ] {
            let pixel = camera.to_screen(at, size).expect("in front of the camera");
            let (origin, dir) = camera.ray(ndc(pixel, size), aspect);
            let picked = scene.pick(origin, dir).map(|(n, _)| n);
            assert_eq!(picked, Some(node), "{view}: the object under {pixel}");
        }
        // Empty ground between them: nothing picked, and the ground point is where it is.
        let between = Vec3::new(-0.5, -2.0, 0.0);
        let pixel = camera.to_screen(between, size).unwrap();
        let (origin, dir) = camera.ray(ndc(pixel, size), aspect);
        assert_eq!(scene.pick(origin, dir), None, "{view}: nothing at {pixel}");
        let ground = camera.ground_point(ndc(pixel, size), aspect, 0.0).unwrap();
        assert!(
            (ground - between).length() < 1e-2,
            "{view}: {ground} is not {between}"
        );
    }
}

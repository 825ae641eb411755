//! A virtual camera renders the scene from its own pose into an off-screen target and hands the
//! picture back: a coloured box in front of it appears where its intrinsics say, and the main
//! view drawn afterwards is unharmed.

use framework::scene::{Object3D, Pixels, Rgba, Scene, VirtualView};
use glam::{Affine3A, Vec2, Vec3};
use image::RgbaImage;
use pv3d::headless::HeadlessGl;
use pv3d::render::{OrbitCamera, SceneBatch, SceneRenderer, ViewTargets};

const MAIN_SIZE: (u32, u32) = (120, 90);
const VIEW_SIZE: (u32, u32) = (160, 120);
const BOX_COLOUR: Rgba = Rgba::rgb(240, 30, 30);

/// A robot at (1, 2) facing +y with a camera 0.3 m up, and a red box 3 m ahead of it, shifted
/// 0.5 m to the robot's left.
fn scene() -> (Scene, framework::scene::ViewOutput, VirtualView, Affine3A) {
    let mut scene = Scene::new();
    let robot_pose = Affine3A::from_rotation_translation(
        glam::Quat::from_rotation_z(std::f32::consts::FRAC_PI_2),
        Vec3::new(1.0, 2.0, 0.0),
    );
    let mut robot = Object3D::new("robot");
    robot.transform = robot_pose;
    let camera_on_robot = Affine3A::from_translation(Vec3::new(0.0, 0.0, 0.3));
    let view = VirtualView::new(
        camera_on_robot,
        60f32.to_radians(),
        VIEW_SIZE.0,
        VIEW_SIZE.1,
    )
    .unwrap();
    let output = view.output.clone();
    robot.geometry.views.push(view.clone());
    scene.add(robot);
    let mut target = Object3D::new("box");
    // 3 m ahead of a robot facing +y is +y in the world; its left is -x.
    target.geometry.cuboid(
        Vec3::new(0.5, 5.0, 0.3),
        Vec3::new(0.4, 0.4, 0.4),
        BOX_COLOUR,
    );
    scene.add(target);
    (scene, output, view, robot_pose * camera_on_robot)
}

/// Draws the virtual views, then the main view, as the window's paint callback does.
fn render(scene: &Scene) -> RgbaImage {
    let gl = HeadlessGl::new(MAIN_SIZE.0, MAIN_SIZE.1).expect("headless GL (Mesa EGL)");
    let mut batch = SceneBatch::default();
    batch.rebuild(scene, None);
    gl.bind();
    let mut renderer = SceneRenderer::new(&gl.gl).expect("renderer");
    renderer.upload(&gl.gl, &batch, 0);
    let mut targets = ViewTargets::new();
    targets
        .render(&gl.gl, &renderer, &batch.views)
        .expect("virtual views");
    let camera = OrbitCamera::default();
    renderer.draw(&gl.gl, camera.view_projection(1.0));
    let image = gl.read_pixels();
    targets.destroy(&gl.gl);
    renderer.destroy(&gl.gl);
    image
}

/// The pixel at `at` (from the lower left, as pictures count rows).
fn pixel(pixels: &Pixels, at: Vec2) -> [u8; 4] {
    let (x, y) = (at.x as usize, at.y as usize);
    let start = (y * pixels.width() as usize + x) * 4;
    pixels.bytes()[start..start + 4].try_into().unwrap()
}

fn is_box(p: [u8; 4]) -> bool {
    p[0] > 120 && p[1] < 60 && p[2] < 60
}

#[test]
fn a_box_ahead_appears_where_the_intrinsics_put_it() {
    let (scene, output, view, camera_to_world) = scene();
    assert!(output.latest().is_none(), "nothing before the first frame");
    let main = render(&scene);
    let picture = output
        .latest()
        .expect("the view was rendered and handed back");
    assert_eq!((picture.width(), picture.height()), VIEW_SIZE);
    save_for_eyes(&picture);

    let centre = view
        .pixel_of(camera_to_world, Vec3::new(0.5, 5.0, 0.3))
        .expect("the box is in view");
    assert!(
        centre.x < VIEW_SIZE.0 as f32 / 2.0,
        "the box is on the camera's left"
    );
    assert!(
        is_box(pixel(&picture, centre)),
        "box colour at {centre}: {:?}",
        pixel(&picture, centre)
    );
    // Just past the box's right edge (world +x is the camera's right) it is background.
    let beside = view
        .pixel_of(camera_to_world, Vec3::new(1.0, 4.8, 0.3))
        .expect("beside the box is in view");
    assert!(
        !is_box(pixel(&picture, beside)),
        "background at {beside}: {:?}",
        pixel(&picture, beside)
    );
    let box_pixels = picture
        .bytes()
        .chunks_exact(4)
        .filter(|p| is_box([p[0], p[1], p[2], p[3]]))
        .count();
    // A 0.4 m face 2.8 m away: focal × 0.4 / 2.8 pixels on a side, give or take its edges.
    let side = view.focal_px() * 0.4 / 2.8;
    let expected = side * side;
    assert!(
        (box_pixels as f32) > expected * 0.7 && (box_pixels as f32) < expected * 1.6,
        "{box_pixels} box pixels, about {expected} expected"
    );
    assert_eq!(
        main.dimensions(),
        MAIN_SIZE,
        "the main view is read back at its own size"
    );
    assert!(
        main.pixels().any(|p| is_box(p.0)),
        "the main view still draws the box after the virtual camera"
    );
}

/// Writes the picture (top row first) where a person can open it.
fn save_for_eyes(picture: &Pixels) {
    let (w, h) = (picture.width(), picture.height());
    let row = w as usize * 4;
    let flipped: Vec<u8> = picture
        .bytes()
        .chunks_exact(row)
        .rev()
        .flatten()
        .copied()
        .collect();
    let out = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("virtual_camera.png");
    RgbaImage::from_raw(w, h, flipped)
        .unwrap()
        .save(&out)
        .unwrap();
}

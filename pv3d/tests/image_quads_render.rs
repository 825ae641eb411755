//! Pictures in the scene are drawn where their node puts them, the right way up, behind lines
//! on the same plane and hidden by solid things above them, and through their filter chain.

mod support;

use framework::scene::{
    FilterChain, ImageQuad, Kernel, Object3D, PixelFormat, Pixels, Rgba, Sampling, Scene,
};
use glam::{Affine3A, Vec2, Vec3};
use pv3d::headless::HeadlessGl;
use pv3d::render::{OrbitCamera, SceneBatch};
use support::draw_batch;

const SIZE: (u32, u32) = (200, 200);

fn render(scene: &Scene) -> (image::RgbaImage, OrbitCamera) {
    let gl = HeadlessGl::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    let mut batch = SceneBatch::default();
    batch.rebuild(scene, None);
    let camera = OrbitCamera {
        distance: 10.0,
        ..OrbitCamera::default()
    };
    (draw_batch(&gl, &batch, &camera, 3.0), camera)
}

fn pixel_at(image: &image::RgbaImage, camera: &OrbitCamera, world: Vec3) -> [u8; 4] {
    let screen = Vec2::new(SIZE.0 as f32, SIZE.1 as f32);
    let at = camera.to_screen(world, screen).unwrap();
    image.get_pixel(at.x as u32, at.y as u32).0
}

/// Red at row 0, column 0; green at row 0, column 1; blue above red; white above green.
fn quadrants() -> Pixels {
    let bytes = [
        [220, 0, 0, 255],
        [0, 220, 0, 255],
        [0, 0, 220, 255],
        [255; 4],
    ]
    .concat();
    Pixels::new(2, 2, PixelFormat::Rgba8, bytes).unwrap()
}

#[test]
fn a_picture_lies_the_right_way_up_behind_lines_and_under_solids() {
    let mut scene = Scene::new();
    let mut map = Object3D::new("map");
    // The node moves the picture: its corner lands at (-2, -2).
    map.transform = Affine3A::from_translation(Vec3::new(-3.0, -2.0, 0.0));
    map.geometry.images.push(ImageQuad::new(
        quadrants(),
        Vec3::new(1.0, 0.0, 0.0),
        Vec2::new(4.0, 4.0),
        Sampling::Nearest,
    ));
    // A line on the picture's plane, across its lower half.
    map.geometry.line(
        Vec3::new(1.0, 1.0, 0.0),
        Vec3::new(5.0, 1.0, 0.0),
        Rgba::rgb(255, 255, 0),
    );
    scene.add(map);
    let mut robot = Object3D::new("robot");
    robot.geometry.cuboid(
        Vec3::new(1.0, 1.0, 0.25),
        Vec3::new(0.6, 0.6, 0.5),
        Rgba::rgb(255, 0, 255),
    );
    scene.add(robot);

    let (image, camera) = render(&scene);
    let out = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("image_quads.png");
    image.save(&out).unwrap();
    let at = |x: f32, y: f32| pixel_at(&image, &camera, Vec3::new(x, y, 0.0));
    let near = |p: [u8; 4], want: [u8; 3]| (0..3).all(|i| p[i].abs_diff(want[i]) < 40);
    assert!(
        near(at(-1.0, -0.5), [220, 0, 0]),
        "red lower left: {:?} ({})",
        at(-1.0, -0.5),
        out.display()
    );
    assert!(
        near(at(1.5, -1.5), [0, 220, 0]),
        "green lower right: {:?}",
        at(1.5, -1.5)
    );
    assert!(
        near(at(-1.0, 1.5), [0, 0, 220]),
        "blue upper left: {:?}",
        at(-1.0, 1.5)
    );
    assert!(
        near(at(-1.5, -1.0), [255, 255, 0]),
        "the line shows on the picture"
    );
    let robot_top = pixel_at(&image, &camera, Vec3::new(1.0, 1.0, 0.5));
    assert!(
        robot_top[0] > 100 && robot_top[1] < 60 && robot_top[2] > 100,
        "the robot above the picture hides it: {robot_top:?}"
    );
    let outside = at(3.0, 3.0);
    assert!(
        outside[0] < 60 && outside[1] < 60,
        "no picture outside its size: {outside:?}"
    );
}

#[test]
fn a_picture_is_drawn_through_its_filter_chain() {
    // One white cell in a black 5 × 5 picture; dilation makes a 3 × 3 white square of it.
    let mut cells = vec![0u8; 25];
    cells[12] = 255;
    let pixels = Pixels::new(5, 5, PixelFormat::Gray8, cells).unwrap();
    let mut quad = ImageQuad::new(
        pixels,
        Vec3::new(-2.5, -2.5, 0.0),
        Vec2::splat(5.0),
        Sampling::Nearest,
    );
    quad.filters = FilterChain(vec![Kernel::Dilate { radius: 1 }]);
    let mut scene = Scene::new();
    let mut node = Object3D::new("grid");
    node.geometry.images.push(quad);
    scene.add(node);

    let (image, camera) = render(&scene);
    let at = |x: f32, y: f32| pixel_at(&image, &camera, Vec3::new(x, y, 0.0));
    for (x, y) in [(0.0, 0.0), (-1.0, -1.0), (1.0, 0.0), (0.0, 1.0)] {
        assert!(at(x, y)[0] > 240, "({x}, {y}) dilated: {:?}", at(x, y));
    }
    for (x, y) in [(-2.0, -2.0), (2.0, 0.0), (0.0, 2.0)] {
        assert!(at(x, y)[0] < 15, "({x}, {y}) still black: {:?}", at(x, y));
    }
}

#[test]
fn a_grid_zoomed_out_keeps_every_one_cell_wall() {
    // 1000 × 1000 free cells with a one-cell wall every 97 columns, drawn 200 pixels wide: five
    // cells to a pixel. Nearest sampling would show one cell of five and lose most walls.
    let side = 1000u32;
    let walls: Vec<u32> = (50..side).step_by(97).collect();
    let cells: Vec<u8> = (0..side * side)
        .map(|k| if walls.contains(&(k % side)) { 25 } else { 235 })
        .collect();
    let pixels = Pixels::new(side, side, PixelFormat::Gray8, cells).unwrap();
    let quad = ImageQuad::new(
        pixels,
        Vec3::new(-5.0, -5.0, 0.0),
        Vec2::splat(10.0),
        Sampling::Grid,
    );
    let mut scene = Scene::new();
    let mut node = Object3D::new("map");
    node.geometry.images.push(quad);
    scene.add(node);
    let gl = HeadlessGl::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    let mut batch = SceneBatch::default();
    batch.rebuild(&scene, None);
    let camera = OrbitCamera {
        distance: 10.0 / (OrbitCamera::default().fov_y / 2.0).tan() / 2.0,
        ..OrbitCamera::default()
    };
    let image = draw_batch(&gl, &batch, &camera, 3.0);
    image
        .save(std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("grid_zoomed_out.png"))
        .unwrap();
    let row = SIZE.1 / 2;
    let dark_runs = (1..SIZE.0)
        .filter(|&x| image.get_pixel(x, row)[0] < 60 && image.get_pixel(x - 1, row)[0] >= 60)
        .count();
    assert_eq!(dark_runs, walls.len(), "every wall shows as a dark column");
}

//! A virtual camera's picture projected onto the ground, end to end: the viewer renders the
//! camera's view, the plugin lays that picture on the ground along the frustum, and the main
//! view shows it there — a red square floating 1 m under a camera 2 m up casts a red square
//! twice its size on the floor, as a projector would.

use framework::PluginConfig;
use framework::config::Param;
use framework::scene::{Object3D, Rgba, Scene};
use framework::testing::Harness;
use glam::{Vec2, Vec3};
use image::RgbaImage;
use pv3d::headless::HeadlessGl;
use pv3d::render::{OrbitCamera, SceneBatch, SceneRenderer, ViewTargets};

const SIZE: (u32, u32) = (200, 200);
const SQUARE_HALF: f32 = 0.25;

/// Renders the scene's virtual views and then the main top view.
fn render(gl: &HeadlessGl, scene: &Scene, camera: &OrbitCamera) -> RgbaImage {
    let mut batch = SceneBatch::default();
    batch.rebuild(scene, None);
    gl.bind();
    let mut renderer = SceneRenderer::new(&gl.gl).expect("renderer");
    renderer.upload(&gl.gl, &batch, 0);
    let mut targets = ViewTargets::new();
    targets.render(&gl.gl, &renderer, &batch.views).unwrap();
    renderer.draw(&gl.gl, camera.view_projection(1.0));
    let image = gl.read_pixels();
    targets.destroy(&gl.gl);
    renderer.destroy(&gl.gl);
    image
}

fn is_red(p: [u8; 4]) -> bool {
    p[0] > 150 && p[1] < 60 && p[2] < 60
}

/// A harness whose scene holds a red square floating 1 m up.
fn floating_square() -> Harness {
    let mut h = Harness::with_registry(plugins::standard_plugins());
    let mut square = Object3D::new("square");
    let c = SQUARE_HALF;
    let red = Rgba::rgb(230, 20, 20);
    for [a, b, d] in [
        [
            Vec3::new(-c, -c, 1.0),
            Vec3::new(c, -c, 1.0),
            Vec3::new(c, c, 1.0),
        ],
        [
            Vec3::new(-c, -c, 1.0),
            Vec3::new(c, c, 1.0),
            Vec3::new(-c, c, 1.0),
        ],
    ] {
        square.geometry.triangle(a, b, d, red);
    }
    h.scene.add(square);
    h
}

/// A camera 2 m up looking straight down, its picture put back as `project` says.
fn camera_looking_down(project: &str) -> PluginConfig {
    PluginConfig {
        library: "libpv3d_virtual_camera".into(),
        params: vec![
            Param::new("pose", "0 0 2 0"),
            Param::new("pitch", "90"),
            Param::new("fov", "60"),
            Param::new("width", "64"),
            Param::new("height", "64"),
            Param::new("showWindow", "0"),
            Param::new("frustumLength", "0"),
            Param::new("project", project),
        ],
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    }
}

#[test]
fn a_floating_square_casts_its_picture_on_the_ground() {
    let mut h = floating_square();
    let config = camera_looking_down("ground");
    let mut plugin = h.make(config).unwrap();

    let gl = HeadlessGl::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    let top = OrbitCamera {
        distance: 4.0,
        ..OrbitCamera::default()
    };
    let before = render(&gl, &h.scene, &top);
    plugin.run(&mut h.ctx()); // takes the rendered picture and projects it
    let after = render(&gl, &h.scene, &top);
    after
        .save(std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("projected_camera.png"))
        .unwrap();

    let at = |image: &RgbaImage, x: f32, y: f32| {
        let p = top
            .to_screen(
                Vec3::new(x, y, 0.0),
                Vec2::new(SIZE.0 as f32, SIZE.1 as f32),
            )
            .unwrap();
        image.get_pixel(p.x as u32, p.y as u32).0
    };
    // Between the square's edge (0.25 m) and its shadow's (0.5 m): only the projection is red.
    for (x, y) in [(0.4, 0.0), (-0.4, 0.0), (0.0, 0.4), (0.0, -0.4), (0.4, 0.4)] {
        assert!(
            !is_red(at(&before, x, y)),
            "({x}, {y}) before: {:?}",
            at(&before, x, y)
        );
        assert!(
            is_red(at(&after, x, y)),
            "({x}, {y}) projected: {:?}",
            at(&after, x, y)
        );
    }
    for (x, y) in [(0.65, 0.0), (0.0, -0.65)] {
        assert!(
            !is_red(at(&after, x, y)),
            "({x}, {y}) beyond: {:?}",
            at(&after, x, y)
        );
    }
}

#[test]
fn the_billboard_floats_straight_up_and_faces_the_eye_from_any_side() {
    let mut h = floating_square();
    let mut plugin = h.make(camera_looking_down("billboard")).unwrap();
    let gl = HeadlessGl::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    let side = |yaw: f32| OrbitCamera {
        projection: pv3d::render::Projection::Perspective,
        centre: Vec3::new(0.0, 0.0, 2.5),
        distance: 5.0,
        pitch: 0.15,
        yaw,
        ..OrbitCamera::default()
    };
    render(&gl, &h.scene, &side(0.0)); // renders the camera's view
    plugin.run(&mut h.ctx()); // takes it and holds it up

    // Straight above the camera, though the camera looks down: its lower edge 0.8 m up.
    let (board, object) = h
        .scene
        .iter()
        .find(|(_, o)| o.name.ends_with("billboard"))
        .expect("the billboard's node");
    let anchor = h.scene.world_transform(board).transform_point3(Vec3::ZERO);
    assert!(anchor.distance(Vec3::new(0.0, 0.0, 2.8)) < 1e-4, "{anchor}");
    assert!(matches!(
        object.geometry.images[0].facing,
        framework::scene::Facing::Viewer { .. }
    ));

    // The square it sees shows as large from the south as from the east.
    let red = |image: &RgbaImage| image.pixels().filter(|p| is_red(p.0)).count();
    let south = red(&render(&gl, &h.scene, &side(0.0)));
    let east_image = render(&gl, &h.scene, &side(std::f32::consts::FRAC_PI_2));
    east_image
        .save(std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("camera_billboard.png"))
        .unwrap();
    let east = red(&east_image);
    assert!(south > 100, "the picture on the board: {south}");
    assert!(
        south.abs_diff(east) * 10 < south,
        "as large from either side: {south} vs {east}"
    );
}

//! Billboards face the viewer: a picture marked `Facing::Viewer` is drawn full width from
//! every side in the perspective view (where the same picture fixed in the world shows only
//! its edge), and lies flat and north up in the top view.

mod support;

use framework::scene::{ImageQuad, Object3D, PixelFormat, Pixels, Sampling, Scene};
use glam::{Affine3A, Vec2, Vec3};
use image::RgbaImage;
use pv3d::headless::HeadlessGl;
use pv3d::render::{OrbitCamera, Projection, SceneBatch};
use support::draw_batch;

const SIZE: (u32, u32) = (240, 240);
/// The picture: 2 m wide, 1 m tall.
const BOARD: Vec2 = Vec2::new(2.0, 1.0);

/// A red picture standing on the middle of its lower edge at (0, 0, 0.5): turned towards the
/// viewer, or fixed upright in the world's x–z plane, facing south.
fn scene(facing_viewer: bool) -> Scene {
    let red = Pixels::new(2, 1, PixelFormat::Rgba8, [[230, 20, 20, 255]; 2].concat()).unwrap();
    let mut scene = Scene::new();
    let mut board = Object3D::new("board");
    board.transform = Affine3A::from_translation(Vec3::new(0.0, 0.0, 0.5));
    let quad = if facing_viewer {
        ImageQuad::billboard(
            red,
            Vec3::ZERO,
            Vec2::new(0.5, 0.0),
            BOARD,
            Sampling::Nearest,
        )
    } else {
        // Its y (rows) turned up to the world's z: a sign facing south.
        board.transform *= Affine3A::from_rotation_x(std::f32::consts::FRAC_PI_2);
        ImageQuad::new(
            red,
            Vec3::new(-BOARD.x / 2.0, 0.0, 0.0),
            BOARD,
            Sampling::Nearest,
        )
    };
    board.geometry.images.push(quad);
    scene.add(board);
    scene
}

fn render(scene: &Scene, camera: &OrbitCamera) -> RgbaImage {
    let gl = HeadlessGl::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    let mut batch = SceneBatch::default();
    batch.rebuild(scene, None);
    draw_batch(&gl, &batch, camera, 3.0)
}

/// The red pixels' bounding box: (columns, rows) spanned, or zero when none.
fn red_extent(image: &RgbaImage) -> (u32, u32) {
    let red: Vec<(u32, u32)> = image
        .enumerate_pixels()
        .filter(|(_, _, p)| p[0] > 150 && p[1] < 80 && p[2] < 80)
        .map(|(x, y, _)| (x, y))
        .collect();
    let span = |of: fn(&(u32, u32)) -> u32| {
        let lo = red.iter().map(of).min();
        let hi = red.iter().map(of).max();
        lo.zip(hi).map_or(0, |(lo, hi)| hi - lo + 1)
    };
    (span(|p| p.0), span(|p| p.1))
}

fn perspective(yaw: f32) -> OrbitCamera {
    OrbitCamera {
        projection: Projection::Perspective,
        distance: 6.0,
        pitch: 0.25,
        yaw,
        centre: Vec3::new(0.0, 0.0, 0.8),
        ..OrbitCamera::default()
    }
}

#[test]
fn a_billboard_turns_to_face_the_eye_from_any_side() {
    let save = |image: &RgbaImage, name: &str| {
        let out = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
        image.save(&out).unwrap();
        out.display().to_string()
    };
    let south = perspective(0.0);
    let east = perspective(std::f32::consts::FRAC_PI_2);

    // Seen from the south, the fixed sign and the billboard look alike.
    let fixed_south = red_extent(&render(&scene(false), &south));
    let board_south = render(&scene(true), &south);
    let (w_south, h_south) = red_extent(&board_south);
    assert!(w_south > 40, "the board shows from the south: {w_south}");
    assert!(
        w_south.abs_diff(fixed_south.0) <= 3,
        "like a sign facing south: {w_south} vs {fixed_south:?}"
    );
    assert!(
        w_south > h_south,
        "2 m wide, 1 m tall: {w_south} × {h_south}"
    );

    // From the east, the fixed sign is edge-on; the billboard has turned to the eye.
    let fixed_east = red_extent(&render(&scene(false), &east));
    let board_east = render(&scene(true), &east);
    let (w_east, h_east) = red_extent(&board_east);
    assert!(
        fixed_east.0 <= 4,
        "a fixed sign seen edge-on is a thin line: {fixed_east:?}"
    );
    assert!(
        w_east.abs_diff(w_south) <= 3 && h_east.abs_diff(h_south) <= 3,
        "the billboard is as wide from the east as from the south: {w_east} × {h_east} vs \
         {w_south} × {h_south} ({}, {})",
        save(&board_south, "billboard_south.png"),
        save(&board_east, "billboard_east.png"),
    );
}

#[test]
fn in_the_top_view_a_billboard_lies_flat_and_north_up() {
    let top = OrbitCamera {
        distance: 6.0,
        ..OrbitCamera::default()
    };
    let image = render(&scene(true), &top);
    let (w, h) = red_extent(&image);
    // Flat, it shows its full 2 × 1 m, wider than tall: seen from above, an upright board
    // would be a line.
    let screen = Vec2::new(SIZE.0 as f32, SIZE.1 as f32);
    let px_per_m = top.to_screen(Vec3::X, screen).unwrap().x - screen.x / 2.0;
    let want = BOARD * px_per_m;
    assert!(
        (w as f32 - want.x).abs() <= 3.0 && (h as f32 - want.y).abs() <= 3.0,
        "{w} × {h}, want {want}"
    );
}

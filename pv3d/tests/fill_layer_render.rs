//! Crowded free space drawn at half resolution ([`pv3d::render::fill_layer`]) must look like the
//! same fills drawn pixel by pixel: the colours agree but for a thin seam along the fills'
//! edges, the outlines and returns drawn over them are untouched, and a few robots' fills
//! (not crowded) are still drawn exactly.

mod support;

use framework::scene::{Object3D, Scene};
use glam::{Affine3A, Quat, Vec2, Vec3};
use image::RgbaImage;
use player_proto::interfaces::laser::LaserScan;
use plugins::laser::{Readings, ScanStyle, scan_geometry};
use pv3d::headless::HeadlessGl;
use pv3d::render::{
    FILLS_IN_LAYER_FROM, OrbitCamera, POINT_SIZE_PX, SceneBatch, SceneRenderer, ScreenDetail,
};

const SIZE: (u32, u32) = (480, 360);

/// `robots` robots 1.5 m apart on a square grid, each with a 181-beam scan whose free space is
/// filled and outlined: up to 3.5 m of reach, so neighbours' fills overlap a few times.
fn swarm(robots: usize) -> Scene {
    let side = (robots as f32).sqrt().ceil() as usize;
    let mut scene = Scene::new();
    let style = ScanStyle {
        fill_cspace: true,
        draw_cspace: true,
        ..ScanStyle::default()
    };
    for i in 0..robots {
        let (x, y) = ((i % side) as f32 * 1.5, (i / side) as f32 * 1.5);
        let ranges = (0..181)
            .map(|b| 1.0 + ((b as f32 * 0.05 + i as f32).sin().abs() * 2.5))
            .collect();
        let scan = LaserScan {
            min_angle: -std::f32::consts::FRAC_PI_2,
            max_angle: std::f32::consts::FRAC_PI_2,
            resolution: std::f32::consts::PI / 180.0,
            max_range: 8.0,
            ranges,
            ..LaserScan::default()
        };
        let mut laser = Object3D::new(format!("laser {i}"));
        laser.transform = Affine3A::from_rotation_translation(
            Quat::from_rotation_z(i as f32 * 0.7),
            Vec3::new(x - side as f32 * 0.75, y - side as f32 * 0.75, 0.0),
        );
        scan_geometry(&Readings::from_scan(&scan), &style, &mut laser.geometry);
        scene.add(laser);
    }
    scene
}

/// The batch for the camera, and pictures of it drawn both ways: (through the layer when
/// crowded, every pixel).
fn draw_both(gl: &HeadlessGl, scene: &Scene, camera: &OrbitCamera) -> (SceneBatch, [RgbaImage; 2]) {
    let aspect = SIZE.0 as f32 / SIZE.1 as f32;
    let view_proj = camera.view_projection(aspect);
    let detail = ScreenDetail::new(
        view_proj,
        Vec2::new(SIZE.0 as f32, SIZE.1 as f32),
        POINT_SIZE_PX,
    );
    let mut batch = SceneBatch::default();
    batch.rebuild(scene, Some(&detail));
    gl.bind();
    let mut renderer = SceneRenderer::new(&gl.gl).expect("renderer");
    renderer.upload(&gl.gl, &batch, 0);
    renderer.draw(&gl.gl, view_proj);
    let layered = gl.read_pixels();
    renderer.draw_every_pixel(&gl.gl, view_proj);
    let exact = gl.read_pixels();
    renderer.destroy(&gl.gl);
    (batch, [layered, exact])
}

/// Per channel: the mean absolute difference, and the share of pixels off by more than 24.
fn difference(a: &RgbaImage, b: &RgbaImage) -> (f64, f64) {
    let (mut sum, mut far, mut n) = (0u64, 0u64, 0u64);
    for (p, q) in a.pixels().zip(b.pixels()) {
        for c in 0..3 {
            let d = u64::from(p.0[c].abs_diff(q.0[c]));
            sum += d;
            far += u64::from(d > 24);
            n += 1;
        }
    }
    (sum as f64 / n as f64, far as f64 / n as f64)
}

#[test]
fn crowded_fills_in_the_layer_look_like_fills_drawn_pixel_by_pixel() {
    let gl = HeadlessGl::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    let camera = OrbitCamera {
        distance: 20.0,
        ..OrbitCamera::default()
    };
    let (batch, [layered, exact]) = draw_both(&gl, &swarm(144), &camera);
    assert!(
        batch.translucent_cover >= FILLS_IN_LAYER_FROM,
        "crowded: the fills cover the view {} times",
        batch.translucent_cover
    );
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"));
    layered.save(dir.join("fills_layered.png")).unwrap();
    exact.save(dir.join("fills_exact.png")).unwrap();
    assert_ne!(layered, exact, "the crowded fills went through the layer");
    let (mean, far) = difference(&layered, &exact);
    eprintln!(
        "cover {:.1}: mean difference {mean:.2}, {:.2} % of channels off by more than 24",
        batch.translucent_cover,
        far * 100.0
    );
    assert!(
        mean < 3.0 && far < 0.03,
        "mean difference {mean:.2}, {:.1} % of channels off by more than 24 (images in {})",
        far * 100.0,
        dir.display()
    );
}

#[test]
fn a_few_robots_fills_are_drawn_exactly() {
    let gl = HeadlessGl::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    let camera = OrbitCamera {
        distance: 40.0,
        ..OrbitCamera::default()
    };
    let (batch, [drawn, exact]) = draw_both(&gl, &swarm(3), &camera);
    assert!(batch.translucent_cover > 0.0 && batch.translucent_cover < FILLS_IN_LAYER_FROM);
    assert_eq!(drawn, exact, "not crowded: no layer");
}

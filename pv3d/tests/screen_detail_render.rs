//! Level of detail must not change what a person sees: a swarm's scans drawn with details
//! finer than a pixel merged paint the same pixels, within the tolerance, as every vertex
//! drawn — while sending the renderer several times fewer primitives.

mod support;

use framework::scene::{Object3D, Scene};
use glam::{Affine3A, Quat, Vec2, Vec3};
use image::RgbaImage;
use player_proto::interfaces::laser::LaserScan;
use plugins::laser::{Readings, ScanStyle, scan_geometry};
use pv3d::headless::HeadlessGl;
use pv3d::render::{OrbitCamera, POINT_SIZE_PX, SceneBatch, ScreenDetail};
use support::draw_batch;

const SIZE: (u32, u32) = (640, 480);

/// 64 robots on an 8 × 8 grid, each with a 361-beam scan of a wavy room: free space
/// outlined (and filled, if `fill`), returns as points.
fn swarm(fill: bool) -> Scene {
    let mut scene = Scene::new();
    let style = ScanStyle {
        fill_cspace: fill,
        draw_cspace: true,
        ..ScanStyle::default()
    };
    for i in 0..64 {
        let (x, y) = ((i % 8) as f32 * 5.0 - 17.5, (i / 8) as f32 * 5.0 - 17.5);
        let ranges = (0..361)
            .map(|b| {
                let wave = (b as f32 * 0.04 + i as f32).sin();
                if b % 90 < 20 {
                    8.0
                } else {
                    1.5 + wave.abs() * 1.5
                }
            })
            .collect();
        let scan = LaserScan {
            min_angle: -std::f32::consts::FRAC_PI_2,
            max_angle: std::f32::consts::FRAC_PI_2,
            resolution: std::f32::consts::PI / 360.0,
            max_range: 8.0,
            ranges,
            ..LaserScan::default()
        };
        let mut laser = Object3D::new(format!("laser {i}"));
        laser.transform = Affine3A::from_rotation_translation(
            Quat::from_rotation_z(i as f32),
            Vec3::new(x, y, 0.0),
        );
        scan_geometry(&Readings::from_scan(&scan), &style, &mut laser.geometry);
        scene.add(laser);
    }
    scene
}

/// Pixels painted in `a` (not background) with no painted pixel of `b` within `reach`.
fn painted_without_neighbour(a: &RgbaImage, b: &RgbaImage, reach: i64) -> usize {
    let background = *a.get_pixel(0, 0);
    let painted = |img: &RgbaImage, x: i64, y: i64| {
        x >= 0
            && y >= 0
            && x < i64::from(img.width())
            && y < i64::from(img.height())
            && *img.get_pixel(x as u32, y as u32) != background
    };
    let mut lonely = 0;
    for y in 0..i64::from(a.height()) {
        for x in 0..i64::from(a.width()) {
            if !painted(a, x, y) {
                continue;
            }
            let near =
                (-reach..=reach).any(|dy| (-reach..=reach).any(|dx| painted(b, x + dx, y + dy)));
            if !near {
                lonely += 1;
            }
        }
    }
    lonely
}

#[test]
fn merged_detail_paints_what_every_vertex_paints() {
    let gl = HeadlessGl::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    gl.bind();
    for (fill, distance) in [(false, 60.0), (false, 20.0), (true, 60.0), (true, 20.0)] {
        let scene = swarm(fill);
        let camera = OrbitCamera {
            distance,
            ..OrbitCamera::default()
        };
        let view_proj = camera.view_projection(SIZE.0 as f32 / SIZE.1 as f32);
        let detail = ScreenDetail::new(
            view_proj,
            Vec2::new(SIZE.0 as f32, SIZE.1 as f32),
            POINT_SIZE_PX,
        );
        let (mut full, mut merged) = (SceneBatch::default(), SceneBatch::default());
        full.rebuild(&scene, None);
        merged.rebuild(&scene, Some(&detail));
        let primitives =
            |b: &SceneBatch| b.lines.len() / 2 + b.points.len() + b.translucent.len() / 3;
        let (every, fewer) = (primitives(&full), primitives(&merged));

        let every_image = draw_batch(&gl, &full, &camera, POINT_SIZE_PX);
        let merged_image = draw_batch(&gl, &merged, &camera, POINT_SIZE_PX);
        let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"));
        every_image
            .save(dir.join(format!("detail_every_{fill}_{distance}.png")))
            .unwrap();
        merged_image
            .save(dir.join(format!("detail_merged_{fill}_{distance}.png")))
            .unwrap();

        let painted = every_image
            .pixels()
            .filter(|p| **p != *every_image.get_pixel(0, 0))
            .count();
        assert!(painted > 10_000, "the swarm shows: {painted} pixels");
        // Lines stray at most a pixel; a left-out point's centre is under a kept point.
        let lost = painted_without_neighbour(&every_image, &merged_image, 2);
        let added = painted_without_neighbour(&merged_image, &every_image, 2);
        assert!(
            (lost + added) * 10_000 < painted,
            "fill {fill}, distance {distance}: {lost} pixels lost, {added} added of {painted} \
             (images in {})",
            dir.display()
        );
        if distance == 60.0 {
            assert!(
                fewer * 3 < every,
                "zoomed out, far fewer primitives: {fewer} of {every}"
            );
        } else {
            assert!(fewer < every, "zoomed in, still fewer: {fewer} of {every}");
        }
    }
}

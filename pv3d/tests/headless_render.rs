//! The renderer draws where the camera says, with no window and no X server.

mod support;

use framework::scene::{Object3D, Rgba, Scene};
use glam::{Affine3A, Vec2, Vec3};
use pv3d::headless::HeadlessGl;
use pv3d::render::{OrbitCamera, SceneBatch};
use support::draw_batch;

fn render(scene: &Scene, camera: &OrbitCamera, size: (u32, u32)) -> image::RgbaImage {
    let gl = HeadlessGl::new(size.0, size.1).expect("headless GL (Mesa EGL)");
    let mut batch = SceneBatch::default();
    batch.rebuild(scene, None);
    draw_batch(&gl, &batch, camera, 5.0)
}

#[test]
fn a_point_and_a_box_land_where_the_camera_projects_them() {
    let mut scene = Scene::new();
    let mut marker = Object3D::new("marker");
    marker.transform = Affine3A::from_translation(Vec3::new(2.0, 1.0, 0.0));
    marker.geometry.point(Vec3::ZERO, Rgba::rgb(255, 0, 0));
    scene.add(marker);
    let mut body = Object3D::new("body");
    body.geometry.cuboid(
        Vec3::new(-2.0, -1.0, 0.25),
        Vec3::new(1.0, 1.0, 0.5),
        Rgba::rgb(0, 200, 0),
    );
    scene.add(body);

    let camera = OrbitCamera {
        distance: 10.0,
        ..OrbitCamera::default()
    };
    let size = (320, 240);
    let image = render(&scene, &camera, size);
    let out = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("headless_render.png");
    image.save(&out).unwrap();

    let screen = Vec2::new(size.0 as f32, size.1 as f32);
    let red_at = camera.to_screen(Vec3::new(2.0, 1.0, 0.0), screen).unwrap();
    let p = image.get_pixel(red_at.x as u32, red_at.y as u32);
    assert!(
        p[0] > 200 && p[1] < 50,
        "red point at {red_at}: {p:?} ({})",
        out.display()
    );

    let green_at = camera
        .to_screen(Vec3::new(-2.0, -1.0, 0.5), screen)
        .unwrap();
    let p = image.get_pixel(green_at.x as u32, green_at.y as u32);
    assert!(
        p[1] > 60 && p[0] < 50,
        "lit green box top at {green_at}: {p:?}"
    );

    let empty = image.get_pixel(5, 5);
    assert!(empty[0] < 60 && empty[1] < 60, "background: {empty:?}");
}

#[test]
fn the_ui_and_the_3d_view_paint_together_offscreen() {
    use pv3d::app::View3d;
    use pv3d::headless::HeadlessUi;

    let mut scene = Scene::new();
    let mut grid = Object3D::new("grid");
    for i in -5..=5 {
        let f = i as f32;
        grid.geometry.line(
            Vec3::new(f, -5.0, 0.0),
            Vec3::new(f, 5.0, 0.0),
            Rgba::rgb(90, 90, 90),
        );
        grid.geometry.line(
            Vec3::new(-5.0, f, 0.0),
            Vec3::new(5.0, f, 0.0),
            Rgba::rgb(90, 90, 90),
        );
    }
    grid.geometry
        .label(Vec3::new(1.0, 1.0, 0.0), "robot r0", Rgba::WHITE);
    scene.add(grid);

    let mut ui = HeadlessUi::new(480, 320).expect("headless GL (Mesa EGL)");
    let mut view = View3d::default();
    view.camera.distance = 8.0;
    for _ in 0..3 {
        ui.run(|ui| {
            eframe::egui::Panel::left("tree")
                .exact_size(120.0)
                .show(ui, |ui| {
                    ui.heading("Items");
                });
            eframe::egui::CentralPanel::default().show(ui, |ui| {
                view.show(ui, &scene);
            });
        });
    }
    let image = ui.read_pixels();
    let out = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("headless_ui.png");
    image.save(&out).unwrap();
    assert_eq!(view.segments, 22);
    // A grid line crosses the middle of the 3D view (x from 120 to 480 → centre 300).
    let centre = image.get_pixel(300, 160);
    assert!(
        centre[0] > 70 && centre[0] < 120,
        "grid line at the view centre: {centre:?} ({})",
        out.display()
    );
}

#[test]
fn labels_that_would_overlap_are_left_out() {
    use pv3d::app::View3d;
    use pv3d::headless::HeadlessUi;

    let mut scene = Scene::new();
    let mut robots = Object3D::new("robots");
    let (red, green, blue) = (
        Rgba::rgb(255, 0, 0),
        Rgba::rgb(0, 255, 0),
        Rgba::rgb(0, 0, 255),
    );
    robots.geometry.label(Vec3::ZERO, "robot1", red);
    robots
        .geometry
        .label(Vec3::new(0.05, 0.05, 0.0), "robot2", green);
    robots
        .geometry
        .label(Vec3::new(0.0, -3.0, 0.0), "robot3", blue);
    scene.add(robots);

    let mut ui = HeadlessUi::new(320, 240).expect("headless GL (Mesa EGL)");
    let mut view = View3d::default();
    view.camera.distance = 8.0;
    for _ in 0..3 {
        ui.run(|ui| {
            eframe::egui::CentralPanel::default().show(ui, |ui| {
                view.show(ui, &scene);
            });
        });
    }
    let image = ui.read_pixels();
    image
        .save(std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("labels.png"))
        .unwrap();
    let count = |want: fn(&image::Rgba<u8>) -> bool| image.pixels().filter(|p| want(p)).count();
    let reds = count(|p| p[0] > 150 && p[1] < 80 && p[2] < 80);
    let greens = count(|p| p[1] > 150 && p[0] < 80 && p[2] < 80);
    let blues = count(|p| p[2] > 150 && p[0] < 80 && p[1] < 80);
    assert!(reds > 20, "the first label is drawn: {reds} pixels");
    assert_eq!(greens, 0, "the one on top of it is left out");
    assert!(blues > 20, "a label with room is drawn: {blues} pixels");
}

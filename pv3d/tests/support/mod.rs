//! What the pv3d tests share: running the binary, drawing a batch offscreen, and counting the
//! pixels of the things the standard plugins draw in their default colours.

#![allow(dead_code)] // each test file uses its own part

pub mod compositions;
pub mod xvfb;

use std::path::Path;
use std::process::{Command, Output};

use image::{Rgba, RgbaImage};
use pv3d::headless::HeadlessGl;
use pv3d::render::{OrbitCamera, SceneBatch, SceneRenderer};

/// The pv3d binary, run from the checkout's top folder (so `stage-worlds/…` and `configs/…`
/// paths work as in the README).
pub fn pv3d() -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_pv3d"));
    command.current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    command
}

/// Runs pv3d and insists it succeeded, showing its stderr if not.
pub fn run_ok(command: &mut Command) -> Output {
    let out = command.output().expect("pv3d runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// Runs pv3d offscreen with `args`, `after` seconds, at `size`, and returns its screenshot.
pub fn screenshot(args: &[&str], after: &str, size: &str, png: &Path) -> RgbaImage {
    let mut command = pv3d();
    command
        .args(args)
        .args([
            "--headless",
            "--after",
            after,
            "--size",
            size,
            "--screenshot",
        ])
        .arg(png);
    let out = run_ok(&mut command);
    // A plugin that could not be made is logged, not fatal: a picture test must not pass
    // over one.
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("ERROR"), "{args:?}: {stderr}");
    image::open(png).expect("a PNG").to_rgba8()
}

pub fn count(image: &RgbaImage, test: impl Fn(&Rgba<u8>) -> bool) -> usize {
    image.pixels().filter(|p| test(p)).count()
}

/// Walls in the ground's default grey (their lit tops and sides).
pub fn wall_pixels(image: &RgbaImage) -> usize {
    count(image, |p| {
        (130..=175).contains(&p[0])
            && (i32::from(p[0]) - i32::from(p[2])).abs() < 20
            && (i32::from(p[0]) - i32::from(p[1])).abs() < 12
    })
}

/// Robot bodies in position2d's default blue.
pub fn robot_pixels(image: &RgbaImage) -> usize {
    count(image, |p| {
        p[2] > 150 && p[0] < 110 && p[1] > 90 && p[1] < 190
    })
}

/// Laser returns and free-space outlines in the laser's default red.
pub fn laser_pixels(image: &RgbaImage) -> usize {
    count(image, |p| {
        p[0] > 200 && (70..=120).contains(&p[1]) && p[2] < 90
    })
}

/// Draws `batch` through `camera` into `gl`'s framebuffer with a fresh renderer (points
/// `point_size` pixels wide) and reads the picture back.
pub fn draw_batch(
    gl: &HeadlessGl,
    batch: &SceneBatch,
    camera: &OrbitCamera,
    point_size: f32,
) -> RgbaImage {
    gl.bind();
    let mut renderer = SceneRenderer::new(&gl.gl).expect("renderer");
    renderer.point_size = point_size;
    renderer.upload(&gl.gl, batch, 0);
    let (w, h) = gl.size();
    renderer.draw(&gl.gl, camera.view_projection(w as f32 / h as f32));
    let image = gl.read_pixels();
    renderer.destroy(&gl.gl);
    image
}

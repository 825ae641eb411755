//! What camera pictures cost a frame, as ratios to the same frame without them: a 640 × 480
//! camera picture arriving every frame and drawn through a 3-kernel chain (blur, Sobel edges,
//! dilation), and one virtual camera rendering the scene at 320 × 240 and reading it back.
//! Headless on Mesa's software renderer, `glFinish` included.
//!
//! `cargo bench -p pv3d --bench camera_frames -- --warm-up-time 1 --measurement-time 5`
//! (needs Mesa's EGL, as the headless tests do: `scripts/setup.sh`).

use criterion::{Criterion, criterion_group, criterion_main};
use eframe::glow::HasContext;
use framework::scene::{
    FilterChain, ImageQuad, Kernel, Object3D, PixelFormat, Pixels, Rgba, Sampling, Scene,
    VirtualView,
};
use glam::{Affine3A, Vec2, Vec3};
use pv3d::headless::HeadlessGl;
use pv3d::render::{OrbitCamera, SceneBatch, SceneRenderer, ViewTargets};

const SIZE: (u32, u32) = (1280, 800);
const CAMERA: (u32, u32) = (640, 480);
const VIRTUAL: (u32, u32) = (320, 240);
const ROBOTS: usize = 16;

/// A floor, a grid of lines and some robots: the frame both cases are compared with.
fn base_scene() -> Scene {
    let mut scene = Scene::new();
    let mut floor = Object3D::new("floor");
    let (a, b, c, d) = (
        Vec3::new(-10.0, -8.0, 0.0),
        Vec3::new(10.0, -8.0, 0.0),
        Vec3::new(10.0, 8.0, 0.0),
        Vec3::new(-10.0, 8.0, 0.0),
    );
    floor.geometry.triangle(a, b, c, Rgba::rgb(60, 64, 70));
    floor.geometry.triangle(a, c, d, Rgba::rgb(60, 64, 70));
    for k in -10..=10 {
        let x = k as f32;
        floor.geometry.line(
            Vec3::new(x, -8.0, 0.0),
            Vec3::new(x, 8.0, 0.0),
            Rgba::rgb(90, 90, 90),
        );
    }
    scene.add(floor);
    for k in 0..ROBOTS {
        let mut robot = Object3D::new(format!("robot {k}"));
        let x = (k % 4) as f32 * 3.0 - 4.5;
        let y = (k / 4) as f32 * 3.0 - 4.5;
        robot.geometry.cuboid(
            Vec3::new(x, y, 0.2),
            Vec3::new(0.5, 0.4, 0.4),
            Rgba::rgb(60, 130, 220),
        );
        scene.add(robot);
    }
    scene
}

/// A camera frame: new pixels (a new generation), so it is uploaded and filtered again.
fn camera_frame(shade: u8) -> Pixels {
    let (w, h) = CAMERA;
    let bytes: Vec<u8> = (0..w * h)
        .flat_map(|k| {
            let (x, y) = (k % w, k / w);
            [(x % 256) as u8, (y % 256) as u8, shade, u8::MAX]
        })
        .collect();
    Pixels::new(w, h, PixelFormat::Rgba8, bytes).expect("a 640 × 480 frame")
}

fn three_kernels() -> FilterChain {
    FilterChain(vec![
        Kernel::Blur { radius: 1 },
        Kernel::SobelEdges,
        Kernel::Dilate { radius: 1 },
    ])
}

fn bench(c: &mut Criterion) {
    let gl = HeadlessGl::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    gl.bind();
    let view_proj = OrbitCamera::default().view_projection(SIZE.0 as f32 / SIZE.1 as f32);
    let mut group = c.benchmark_group("camera_frames");
    group.sample_size(20);

    // A new camera frame every frame: the batch is rebuilt (the scene changed), the picture
    // uploaded and filtered, the view drawn. The baseline rebuilds and draws the same scene.
    let frames = [camera_frame(0), camera_frame(128)];
    for (name, chain) in [
        ("no_camera", None),
        ("camera_640x480_unfiltered", Some(FilterChain::default())),
        ("camera_640x480_3_kernels", Some(three_kernels())),
    ] {
        let mut scene = base_scene();
        let holder = scene.add(Object3D::new("camera picture"));
        let mut renderer = SceneRenderer::new(&gl.gl).expect("renderer");
        let mut batch = SceneBatch::default();
        let mut revision = 0u64;
        group.bench_function(format!("new_frame_{name}"), |b| {
            b.iter(|| {
                revision += 1;
                if let Some(chain) = &chain {
                    // The same bytes, but new pixels: what a camera's next frame is.
                    let frame = &frames[(revision % 2) as usize];
                    let fresh = Pixels::new(
                        frame.width(),
                        frame.height(),
                        frame.format(),
                        frame.bytes().to_vec(),
                    )
                    .expect("same size");
                    let mut quad = ImageQuad::new(
                        fresh,
                        Vec3::new(-3.2, -2.4, 0.01),
                        Vec2::new(6.4, 4.8),
                        Sampling::Linear,
                    );
                    quad.filters = chain.clone();
                    let object = scene.get_mut(holder).expect("holder");
                    object.geometry.images.clear();
                    object.geometry.images.push(quad);
                } else {
                    scene.get_mut(holder);
                }
                batch.rebuild(&scene, None);
                renderer.upload(&gl.gl, &batch, revision);
                renderer.draw(&gl.gl, view_proj);
                // SAFETY: the context is current on this thread.
                unsafe { gl.gl.finish() };
            })
        });
        renderer.destroy(&gl.gl);
    }

    // One virtual camera: the scene rendered at 320 × 240 and read back before each frame.
    for (name, with_view) in [
        ("no_virtual_camera", false),
        ("virtual_camera_320x240", true),
    ] {
        let mut scene = base_scene();
        if with_view {
            let mut post = Object3D::new("virtual camera");
            post.transform = Affine3A::from_translation(Vec3::new(-8.0, 0.0, 1.5));
            let view = VirtualView::new(
                Affine3A::from_rotation_y(0.3),
                60f32.to_radians(),
                VIRTUAL.0,
                VIRTUAL.1,
            )
            .expect("a valid camera");
            post.geometry.views.push(view);
            scene.add(post);
        }
        let mut batch = SceneBatch::default();
        batch.rebuild(&scene, None);
        let mut renderer = SceneRenderer::new(&gl.gl).expect("renderer");
        renderer.upload(&gl.gl, &batch, 0);
        let mut targets = ViewTargets::new();
        group.bench_function(format!("draw_{name}"), |b| {
            b.iter(|| {
                targets
                    .render(&gl.gl, &renderer, &batch.views)
                    .expect("virtual views");
                renderer.draw(&gl.gl, view_proj);
                // SAFETY: the context is current on this thread.
                unsafe { gl.gl.finish() };
            })
        });
        targets.destroy(&gl.gl);
        renderer.destroy(&gl.gl);
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

//! What one redraw of a swarm costs: 256 robots, each a position2d body and a 361-beam laser
//! (scan points and free-space outline), all with new data every frame — the plugins' update,
//! the scene batch, the upload and the draw on Mesa's software renderer (glFinish included) —
//! against two floors measured in the same run: the same frame drawn from prebuilt buffers
//! (drawing alone), and the same number of line segments from one prebuilt buffer. Each is
//! measured twice: with every vertex drawn, and with details finer than a pixel merged as
//! pv3d draws them (`ScreenDetail`). The `step_*` lines say where a frame's time goes.
//!
//! `cargo bench -p pv3d --bench frame -- --warm-up-time 1 --measurement-time 5`
//! (needs Mesa's EGL, as the headless tests do: `scripts/setup.sh`).

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Instant;

use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, Criterion, criterion_group, criterion_main};
use eframe::glow::HasContext;
use framework::device::{DeviceAccess, RecordingDevice};
use glam::Vec2;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::interfaces::position2d::{Position2d, Position2dData};
use player_proto::message::Message;
use player_proto::{DevAddr, Interface, MsgType};
use pv3d::app::Viewer;
use pv3d::composition::{Composition, FoundDevice, ParserRegistry, instantiate, parse_str};
use pv3d::headless::{HeadlessGl, HeadlessUi};
use pv3d::render::{OrbitCamera, POINT_SIZE_PX, SceneBatch, SceneRenderer, ScreenDetail};

const ROBOTS: u16 = 256;
const BEAMS: usize = 361;
const SIZE: (u32, u32) = (1280, 800);

fn composition(fill: bool) -> Composition {
    let text = format!(
        r#"<pv3d><handlers>
  <playerDeviceMask interface="position2d">
    <plugin library="libpv3d_position2d" id="robot"><trailLength>0</trailLength></plugin>
  </playerDeviceMask>
  <playerDeviceMask interface="laser">
    <plugin library="libpv3d_laser" id="laser">
      <parentNode interface="position2d" index="0"/>
      <fillLaserCspace>{}</fillLaserCspace><drawLaserCspace>1</drawLaserCspace>
    </plugin>
  </playerDeviceMask>
</handlers></pv3d>"#,
        u8::from(fill)
    );
    let root = parse_str(&text, Arc::new(PathBuf::from("frame-bench.xml"))).expect("xml");
    Composition::from_root(&root, &ParserRegistry::default()).expect("composition")
}

/// A swarm of robots on a 16 × 16 grid, with their devices kept in memory.
/// Where each robot's data comes from: every robot has its own port, and index 0 of each.
const POSITION2D_0: DevAddr = DevAddr {
    host: 0,
    robot: 0,
    interf: Interface::POSITION2D,
    index: 0,
};
const LASER_0: DevAddr = DevAddr {
    host: 0,
    robot: 0,
    interf: Interface::LASER,
    index: 0,
};

struct Swarm {
    viewer: Viewer,
    devices: Vec<(u16, Arc<RecordingDevice>, Arc<RecordingDevice>)>,
    frame: u32,
}

impl Swarm {
    fn new(fill: bool) -> Swarm {
        let mut found = Vec::new();
        let mut links: HashMap<(u16, Interface), Arc<RecordingDevice>> = HashMap::new();
        let mut devices = Vec::new();
        for port in 1..=ROBOTS {
            for interf in [Interface::POSITION2D, Interface::LASER] {
                found.push(FoundDevice {
                    host: "swarm".into(),
                    port,
                    addr: DevAddr {
                        interf,
                        ..DevAddr::default()
                    },
                    driver: "stage".into(),
                });
                links.insert((port, interf), Arc::default());
            }
            devices.push((
                port,
                links[&(port, Interface::POSITION2D)].clone(),
                links[&(port, Interface::LASER)].clone(),
            ));
        }
        let instances = instantiate(&composition(fill), &found);
        let viewer = Viewer::new(instances, plugins::standard_plugins(), &|d| {
            links
                .get(&(d.port, d.addr.interf))
                .map(|l| l.clone() as Arc<dyn DeviceAccess>)
        });
        assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
        let mut swarm = Swarm {
            viewer,
            devices,
            frame: 0,
        };
        swarm.new_data();
        swarm.viewer.update(Instant::now());
        swarm.assert_spread();
        swarm
    }

    /// The robots stand where their odometry puts them, apart on a 16 × 16 grid — not all at
    /// the origin, as they did while the data was addressed to no interface (a figure of 256
    /// robots drawn on top of one another measures nothing real).
    fn assert_spread(&self) {
        let scene = self.viewer.scene();
        let mut places: Vec<(i32, i32)> = scene
            .iter()
            .filter(|(_, o)| o.has_tag("robot"))
            .map(|(id, _)| {
                let at = scene.world_transform(id).translation;
                (at.x.round() as i32, at.y.round() as i32)
            })
            .collect();
        places.sort_unstable();
        places.dedup();
        assert_eq!(
            places.len(),
            usize::from(ROBOTS),
            "robots apart: {places:?}"
        );
    }

    /// Every robot moves a little and scans again.
    fn new_data(&mut self) {
        self.frame += 1;
        let t = self.frame as f32 * 0.01;
        for (port, base, laser) in &self.devices {
            let i = f32::from(*port - 1);
            let (x, y) = ((i % 16.0) * 4.0 - 30.0, (i / 16.0).floor() * 4.0 - 30.0);
            base.push(Message::typed(
                POSITION2D_0,
                MsgType::Data,
                Position2d::State(Position2dData {
                    pos: Pose2d {
                        px: f64::from(x + t.sin()),
                        py: f64::from(y),
                        pa: f64::from(t + i),
                    },
                    ..Position2dData::default()
                }),
            ));
            let ranges = (0..BEAMS)
                .map(|b| 1.0 + ((b as f32 * 0.05 + t + i).sin() + 1.0) * 1.5)
                .collect();
            laser.push(Message::typed(
                LASER_0,
                MsgType::Data,
                Laser::Scan(LaserScan {
                    min_angle: -std::f32::consts::FRAC_PI_2,
                    max_angle: std::f32::consts::FRAC_PI_2,
                    resolution: std::f32::consts::PI / (BEAMS - 1) as f32,
                    max_range: 8.0,
                    ranges,
                    ..LaserScan::default()
                }),
            ));
        }
    }
}

fn camera() -> OrbitCamera {
    OrbitCamera {
        distance: 80.0,
        ..OrbitCamera::default()
    }
}

fn frames(c: &mut Criterion) {
    let gl = HeadlessGl::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    gl.bind();
    let view_proj = camera().view_projection(SIZE.0 as f32 / SIZE.1 as f32);
    let screen = ScreenDetail::new(
        view_proj,
        Vec2::new(SIZE.0 as f32, SIZE.1 as f32),
        POINT_SIZE_PX,
    );
    let mut group = c.benchmark_group("redraw_256_robots");
    group.sample_size(20);

    for fill in [false, true] {
        let mut swarm = Swarm::new(fill);
        let mut renderer = SceneRenderer::new(&gl.gl).expect("renderer");
        let mut batch = SceneBatch::default();
        swarm.viewer.update(Instant::now());
        let style = if fill {
            "with_filled_free_space"
        } else {
            "outlines"
        };
        // Every vertex drawn (as before level of detail), then what pv3d draws: details
        // finer than a pixel merged.
        for (detail, name) in [(None, "every_vertex"), (Some(&screen), "screen_detail")] {
            batch.rebuild(swarm.viewer.scene(), detail);
            println!("{style}, {name}: {}", counts(&batch));
            let mut revision = 0;
            group.bench_function(format!("frame_{style}_{name}"), |b| {
                b.iter(|| {
                    swarm.new_data();
                    swarm.viewer.update(Instant::now());
                    batch.rebuild(swarm.viewer.scene(), detail);
                    revision += 1;
                    renderer.upload(&gl.gl, &batch, revision);
                    renderer.draw(&gl.gl, view_proj);
                    // SAFETY: the context is current on this thread.
                    unsafe { gl.gl.finish() };
                })
            });
        }
        if !fill {
            steps(&mut group, &gl, &mut swarm, &mut renderer, &screen);
            // The floors: the same segments, uploaded once, drawn from one buffer; and the
            // same frame, everything prebuilt (what drawing alone costs).
            for (detail, name) in [(None, "every_vertex"), (Some(&screen), "screen_detail")] {
                batch.rebuild(swarm.viewer.scene(), detail);
                let mut segments_only = SceneBatch::default();
                segments_only.lines = batch.lines.clone();
                for (floor, what) in [(&segments_only, "segments"), (&batch, "frame")] {
                    let mut prebuilt = SceneRenderer::new(&gl.gl).expect("renderer");
                    prebuilt.upload(&gl.gl, floor, 0);
                    group.bench_function(format!("floor_same_{what}_prebuilt_{name}"), |b| {
                        b.iter(|| {
                            prebuilt.draw(&gl.gl, view_proj);
                            // SAFETY: the context is current on this thread.
                            unsafe { gl.gl.finish() };
                        })
                    });
                    prebuilt.destroy(&gl.gl);
                }
            }
        }
        renderer.destroy(&gl.gl);
    }
    group.finish();
}

/// Where a frame's time goes, step by step (what pv3d draws: screen detail).
fn steps(
    group: &mut BenchmarkGroup<'_, WallTime>,
    gl: &HeadlessGl,
    swarm: &mut Swarm,
    renderer: &mut SceneRenderer,
    screen: &ScreenDetail,
) {
    let view_proj = camera().view_projection(SIZE.0 as f32 / SIZE.1 as f32);
    let mut batch = SceneBatch::default();
    group.bench_function("step_plugins_update", |b| {
        b.iter(|| {
            swarm.new_data();
            swarm.viewer.update(Instant::now());
        })
    });
    group.bench_function("step_batch_rebuild_every_vertex", |b| {
        b.iter(|| batch.rebuild(swarm.viewer.scene(), None))
    });
    group.bench_function("step_batch_rebuild_screen_detail", |b| {
        b.iter(|| batch.rebuild(swarm.viewer.scene(), Some(screen)))
    });
    let mut revision = u64::MAX;
    group.bench_function("step_upload", |b| {
        b.iter(|| {
            revision -= 1;
            renderer.upload(&gl.gl, &batch, revision);
            // SAFETY: the context is current on this thread.
            unsafe { gl.gl.finish() };
        })
    });
    group.bench_function("step_upload_draw", |b| {
        b.iter(|| {
            revision -= 1;
            renderer.upload(&gl.gl, &batch, revision);
            renderer.draw(&gl.gl, view_proj);
            // SAFETY: the context is current on this thread.
            unsafe { gl.gl.finish() };
        })
    });
}

fn counts(batch: &SceneBatch) -> String {
    format!(
        "{} line segments, {} points, {} opaque and {} translucent triangles, {} mesh triangles",
        batch.segment_count(),
        batch.points.len(),
        batch.triangles.len() / 3,
        batch.translucent.len() / 3,
        batch.mesh.len() / 3
    )
}

/// The whole window's pass offscreen, as `--screenshot` runs it: the plugins' update, egui's
/// layout of the item tree (every plugin a row), the status panel and the labels, and the
/// 3D view painted through our renderer — against the frame alone above.
fn window_frames(c: &mut Criterion) {
    let mut ui = HeadlessUi::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    let mut group = c.benchmark_group("redraw_256_robots");
    group.sample_size(20);
    let mut swarm = Swarm::new(true);
    group.bench_function("window_pass_with_filled_free_space", |b| {
        b.iter(|| {
            swarm.new_data();
            swarm.viewer.update(Instant::now());
            ui.run(|ui| swarm.viewer.ui(ui));
            ui.finish();
        })
    });
    group.finish();
}

criterion_group!(benches, frames, window_frames);
criterion_main!(benches);

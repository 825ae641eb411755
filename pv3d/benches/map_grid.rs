//! What a 4000 × 4000 occupancy grid costs to draw through the map plugin's scene (one grey
//! texture with darkest-cell mipmaps), against the floor measured in the same run: one
//! textured quad of the same size and texture size with nothing else. Also, once each: the
//! plugin assembling the grid from its 49 tiles, the first upload (texture and mipmaps), and
//! a dilation by a robot's radius run on the GPU. Mesa's software renderer, glFinish included.
//!
//! `cargo bench -p pv3d --bench map_grid -- --warm-up-time 1 --measurement-time 5`
//! (needs Mesa's EGL, as the headless tests do: `scripts/setup.sh`).

use std::time::{Duration, Instant};

use criterion::{Criterion, criterion_group, criterion_main};
use eframe::glow::HasContext;
use framework::config::{Param, PluginConfig};
use framework::plugin::Plugin;
use framework::scene::{ImageQuad, Object3D, PixelFormat, Pixels, Sampling, Scene};
use framework::testing::Harness;
use glam::{Vec2, Vec3};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::map::{Map, MapData, MapInfo};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use pv3d::headless::HeadlessGl;
use pv3d::render::{OrbitCamera, SceneBatch, SceneRenderer};

const CELLS: u32 = 4000;
const SCALE: f32 = 0.05;
const SIZE: (u32, u32) = (1280, 800);

/// Rooms 10 m square with one-cell walls and doors, an unknown border.
fn cell(i: u32, j: u32) -> i8 {
    let room = (10.0 / SCALE) as u32;
    let (ri, rj) = (i % room, j % room);
    let door = (room / 2..room / 2 + 20).contains(&ri) || (room / 2..room / 2 + 20).contains(&rj);
    if i < 100 || j < 100 {
        0
    } else if (ri == 0 || rj == 0) && !door {
        1
    } else {
        -1
    }
}

fn map_config(params: Vec<Param>) -> PluginConfig {
    PluginConfig {
        library: "libpv3d_map".into(),
        id: "map".into(),
        params,
        ..PluginConfig::default()
    }
}

/// The map plugin made and fed every tile; the tiles are compressed beforehand so that only
/// the plugin's own work is timed. Returns the harness and how long the plugin took.
fn loaded_map(params: Vec<Param>, tiles: &[MapData]) -> (Harness, Box<dyn Plugin>, Duration) {
    let addr: DevAddr = "map:0".parse().unwrap();
    let mut h = Harness::with_registry(plugins::standard_plugins());
    let info = MapInfo {
        scale: SCALE,
        width: CELLS,
        height: CELLS,
        origin: Pose2d::new(-100.0, -100.0, 0.0),
    };
    h.device.reply_to(
        Map::REQ_GET_INFO.kind(),
        Ok(Message::typed(addr, MsgType::Ack, Map::Info(info))),
    );
    let started = Instant::now();
    let mut plugin = h.make(map_config(params)).expect("map plugin");
    let mut answered = 0;
    while answered < tiles.len() || !h.device.pending.lock().unwrap().is_empty() {
        plugin.run(&mut h.ctx());
        let pending: Vec<_> = h.device.pending.lock().unwrap().drain(..).collect();
        for (_, responder) in pending {
            let tile = tiles[answered].clone();
            answered += 1;
            responder.answer(Ok(Message::typed(addr, MsgType::Ack, Map::Tile(tile))));
        }
    }
    plugin.run(&mut h.ctx());
    (h, plugin, started.elapsed())
}

fn compressed_tiles() -> Vec<MapData> {
    let side = plugins::map::grid::TILE_SIDE;
    let mut tiles = Vec::new();
    for row in (0..CELLS).step_by(side as usize) {
        for col in (0..CELLS).step_by(side as usize) {
            let (w, h) = (side.min(CELLS - col), side.min(CELLS - row));
            let cells: Vec<i8> = (0..h)
                .flat_map(|j| (0..w).map(move |i| cell(col + i, row + j)))
                .collect();
            tiles.push(MapData::compress(col, row, w, h, 1, &cells));
        }
    }
    tiles
}

/// One uniform quad of the same size, texture and footprint: the floor.
fn one_quad() -> Scene {
    let pixels = Pixels::new(
        CELLS,
        CELLS,
        PixelFormat::Gray8,
        vec![200u8; (CELLS * CELLS) as usize],
    )
    .unwrap();
    let side = CELLS as f32 * SCALE;
    let mut scene = Scene::new();
    let mut node = Object3D::new("quad");
    node.geometry.images.push(ImageQuad::new(
        pixels,
        Vec3::new(-100.0, -100.0, 0.0),
        Vec2::splat(side),
        Sampling::Nearest,
    ));
    scene.add(node);
    scene
}

fn camera() -> OrbitCamera {
    // The whole 200 m map in view: about six cells to a pixel.
    OrbitCamera {
        distance: 250.0,
        ..OrbitCamera::default()
    }
}

fn bench(c: &mut Criterion) {
    let gl = HeadlessGl::new(SIZE.0, SIZE.1).expect("headless GL (Mesa EGL)");
    gl.bind();
    let view_proj = camera().view_projection(SIZE.0 as f32 / SIZE.1 as f32);
    let tiles = compressed_tiles();
    let (h, _plugin, assembled) = loaded_map(vec![], &tiles);
    println!("map plugin: info and 49 tiles to a scene picture in {assembled:?}");

    let mut group = c.benchmark_group("map_grid_4000");
    group.sample_size(20);
    for (name, scene) in [
        ("map_plugin_scene", &h.scene),
        ("one_textured_quad", &one_quad()),
    ] {
        let mut batch = SceneBatch::default();
        batch.rebuild(scene, None);
        let mut renderer = SceneRenderer::new(&gl.gl).expect("renderer");
        let started = Instant::now();
        renderer.upload(&gl.gl, &batch, 0);
        // SAFETY: the context is current on this thread.
        unsafe { gl.gl.finish() };
        println!("{name}: first upload {:?}", started.elapsed());
        group.bench_function(format!("draw_{name}"), |b| {
            b.iter(|| {
                renderer.draw(&gl.gl, view_proj);
                // SAFETY: the context is current on this thread.
                unsafe { gl.gl.finish() };
            })
        });
        // A camera move: the batch is rebuilt and "uploaded", the texture is kept.
        let mut revision = 0;
        group.bench_function(format!("rebuild_upload_draw_{name}"), |b| {
            b.iter(|| {
                batch.rebuild(scene, None);
                revision += 1;
                renderer.upload(&gl.gl, &batch, revision);
                renderer.draw(&gl.gl, view_proj);
                // SAFETY: the context is current on this thread.
                unsafe { gl.gl.finish() };
            })
        });
        renderer.destroy(&gl.gl);
    }
    group.finish();

    // Once: a robot's configuration space, 0.3 m = 6 cells, on the GPU.
    let mut dilate = Param::new("filter", "dilate");
    dilate.attributes = vec![("radius".into(), "0.3".into())];
    let (h, _plugin, _) = loaded_map(vec![dilate], &tiles);
    let mut batch = SceneBatch::default();
    batch.rebuild(&h.scene, None);
    let mut renderer = SceneRenderer::new(&gl.gl).expect("renderer");
    let started = Instant::now();
    renderer.upload(&gl.gl, &batch, 0);
    // SAFETY: the context is current on this thread.
    unsafe { gl.gl.finish() };
    println!(
        "map plugin scene, dilated by 0.3 m: first upload and filter {:?}",
        started.elapsed()
    );
    renderer.destroy(&gl.gl);
}

criterion_group!(benches, bench);
criterion_main!(benches);

//! Shared helpers for the workspace integration tests (see `tests/tests/`): a Stage world
//! served by player-sim over real TCP, and a pv3d viewer built from a composition against it,
//! by the builder `pv3d` uses ([`ViewerBuilder`]) but without a window, so a test can click and
//! step it.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use player_sim::serve::{Running, ServeOptions};
use pv3d::app::{Viewer, ViewerBuilder};
use pv3d::composition::{Composition, ParserRegistry};

/// The checkout's top folder.
pub fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ lies in the checkout")
        .to_path_buf()
}

/// Loads compositions given relative to the checkout.
pub fn load(files: &[&str]) -> Composition {
    let paths: Vec<PathBuf> = files.iter().map(|f| repo_root().join(f)).collect();
    Composition::load_files(&paths, &ParserRegistry::standard())
        .unwrap_or_else(|e| panic!("{files:?} should load: {e}"))
}

/// A viewer with its robots, as `pv3d` makes it (with no window to wake).
pub fn viewer_for(composition: &Composition) -> Viewer {
    ViewerBuilder::new(composition.clone())
        .connect_timeout(Duration::from_secs(5))
        .build()
}

/// Serves `world` (relative to the checkout) on free ports for `composition`.
pub fn serve(world: &str, composition: &mut Composition, speedup: f64) -> Running {
    let options = ServeOptions {
        speedup,
        ..ServeOptions::default()
    };
    pv3d::embedded_world::serve_world(&repo_root().join(world), composition, options)
        .unwrap_or_else(|e| panic!("{world} should serve: {e}"))
}

/// Updates the viewer every 20 ms, as the window does, until `done` holds; panics naming
/// `what` after `timeout`.
pub fn run_until(
    viewer: &mut Viewer,
    what: &str,
    timeout: Duration,
    mut done: impl FnMut(&mut Viewer) -> bool,
) {
    let deadline = Instant::now() + timeout;
    loop {
        viewer.update(Instant::now());
        if done(viewer) {
            return;
        }
        assert!(Instant::now() < deadline, "timed out waiting for {what}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// The simulated pose (x, y, heading) of robot `index`.
pub fn sim_pose(running: &Running, index: usize) -> (f64, f64, f64) {
    let sim = running.sim.lock().expect("simulation");
    let pose = sim.robots[index].pose;
    (pose.x, pose.y, pose.a)
}

/// Updates the viewer every 20 ms, as the window does, for `duration`.
pub fn run_for(viewer: &mut Viewer, duration: Duration) {
    let until = Instant::now() + duration;
    while Instant::now() < until {
        viewer.update(Instant::now());
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// A port on 127.0.0.1 that nobody listens on (yet).
pub fn unused_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("a free port")
        .port()
}

/// Points every Player client of `composition` at 127.0.0.1:`port`.
pub fn point_at(composition: &mut Composition, port: u16) {
    for client in &mut composition.clients {
        client.host = "127.0.0.1".into();
        client.port = port;
    }
}

/// Serves `world` (relative to the checkout) with every device on one given port, as a
/// server restarted on its old port, or started after the viewer, would be.
pub fn serve_on_port(world: &str, port: u16) -> Running {
    serve_some_on_port(world, port, |_| true)
}

/// [`serve_on_port`] with only the devices `keep` keeps: a server restarted with a device
/// fewer.
pub fn serve_some_on_port(
    world: &str,
    port: u16,
    keep: impl Fn(&player_sim::served::ServedDevice) -> bool,
) -> Running {
    use player_sim::{served::from_cfg, sim::Simulation, world::World};
    let world_file = repo_root().join(world);
    let world = World::load(&world_file).expect("world");
    let mut devices =
        from_cfg(&world_file.with_extension("cfg"), &world, &mut Vec::new()).expect("cfg");
    devices.retain(|device| keep(device));
    for device in &mut devices {
        device.port = port;
    }
    player_sim::serve::serve(Simulation::new(world), devices, ServeOptions::default())
        .expect("the server starts")
}

/// Every text one UI pass of `viewer` draws in a 1200×800 window laid out by `egui_ctx` (its
/// plugins' windows and the status panel included). Nothing is painted: the font texture
/// uploads are dropped on purpose. Windows that open on a click keep their state in
/// `egui_ctx`, so pass the same one to successive passes.
pub fn texts_drawn(viewer: &mut Viewer, egui_ctx: &egui::Context) -> Vec<String> {
    use egui::{Pos2, RawInput, Rect, Shape, vec2};
    let input = RawInput {
        screen_rect: Some(Rect::from_min_size(Pos2::ZERO, vec2(1200.0, 800.0))),
        ..Default::default()
    };
    let mut output = egui_ctx.run_ui(input, |ui| viewer.ui(ui));
    output.textures_delta.clear();
    let mut shapes: Vec<Shape> = output.shapes.into_iter().map(|c| c.shape).collect();
    let mut texts = Vec::new();
    while let Some(shape) = shapes.pop() {
        match shape {
            Shape::Text(text) => texts.push(text.galley.text().to_string()),
            Shape::Vec(inner) => shapes.extend(inner),
            _ => {}
        }
    }
    texts
}

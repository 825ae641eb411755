//! What the world and simulation tests share: the shipped worlds, a scratch world file,
//! stepping a simulation for so many simulated seconds, navigation.world served over TCP, a
//! free port, and waiting — bounded in time — for what a server sends.

#![allow(dead_code)] // each test file uses its own part

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use player_sim::serve::{Running, ServeOptions, serve};
use player_sim::served::{cfgs_beside, from_cfgs};
use player_sim::sim::Simulation;
use player_sim::world::World;

pub fn worlds() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds")
}

pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// A port nobody listens on right now (the system's choice, released at once).
pub fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port()
}

pub fn run(sim: &mut Simulation, seconds: f64) {
    for _ in 0..(seconds / sim.world.interval).round() as usize {
        sim.step();
    }
}

/// `get`'s first `Some`, asked every few milliseconds; panics naming `what` after `timeout`.
pub fn wait_for<T>(what: &str, timeout: Duration, mut get: impl FnMut() -> Option<T>) -> T {
    let deadline = Instant::now() + timeout;
    loop {
        if let Some(v) = get() {
            return v;
        }
        assert!(Instant::now() < deadline, "timed out waiting for {what}");
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// stage-worlds/navigation.world with every .cfg beside it, served on free ports at `speedup`.
pub fn serve_navigation(speedup: f64) -> Running {
    let world_file = worlds().join("navigation.world");
    let world = World::load(&world_file).unwrap();
    let cfgs = cfgs_beside(&world_file);
    assert_eq!(
        cfgs.len(),
        3,
        "navigation.cfg, navigation-sim.cfg and navigation-nav.cfg: {cfgs:?}"
    );
    let paths: Vec<_> = cfgs.iter().map(|p| p.as_path()).collect();
    let devices = from_cfgs(&paths, &world, &mut Vec::new()).unwrap();
    let options = ServeOptions {
        speedup,
        free_ports: true,
        ..ServeOptions::default()
    };
    serve(Simulation::new(world), devices, options).unwrap()
}

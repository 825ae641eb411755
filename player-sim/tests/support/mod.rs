//! What the world and simulation tests share: the shipped worlds, a scratch world file, and
//! stepping a simulation for so many simulated seconds.

#![allow(dead_code)] // each test file uses its own part

use std::path::{Path, PathBuf};

use player_sim::sim::Simulation;

pub fn worlds() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds")
}

pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

pub fn run(sim: &mut Simulation, seconds: f64) {
    for _ in 0..(seconds / sim.world.interval).round() as usize {
        sim.step();
    }
}

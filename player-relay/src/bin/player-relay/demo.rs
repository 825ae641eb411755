//! `player-relay --demo` and `--world FILE`: a world served in-process, so that one command
//! shows robots in a browser (`--web`), in Foxglove or in Zenoh with nothing else running.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use player_sim::serve::{Running, ServeOptions};
use player_sim::served::devices_beside;
use player_sim::sim::Simulation;
use player_sim::world::World;

/// The demo's world: from the current directory when it is a checkout, else from the
/// checkout this program was built from.
pub fn world_file() -> PathBuf {
    let here = Path::new("stage-worlds/multirobot.world");
    if here.exists() {
        return here.to_path_buf();
    }
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../stage-worlds/multirobot.world"
    ))
    .to_path_buf()
}

/// Serves the robots of the world at `path` on free local ports.
pub fn serve(path: &Path) -> Result<Running> {
    let path = path.to_path_buf();
    let world = World::load(&path).with_context(|| format!("loading {}", path.display()))?;
    let mut ignored = Vec::new();
    let devices = devices_beside(&path, &world, &mut ignored)?;
    for note in ignored {
        tracing::info!("{}: {note}", path.display());
    }
    let options = ServeOptions {
        free_ports: true,
        ..ServeOptions::default()
    };
    let running = player_sim::serve::serve(Simulation::new(world), devices, options)?;
    eprintln!(
        "simulating {} robots of {}",
        running.ports.len(),
        path.display()
    );
    Ok(running)
}

//! `player-relay --demo` and `--world FILE`: a world served in-process, so that one command
//! shows robots in a browser (`--web`), in Foxglove or in Zenoh with nothing else running.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use player_sim::serve::{Running, ServeOptions, serve_world_file};

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
    let options = ServeOptions {
        free_ports: true,
        ..ServeOptions::default()
    };
    let mut ignored = Vec::new();
    let running = serve_world_file(path, options, &[], &mut ignored)
        .with_context(|| format!("simulating {}", path.display()))?;
    for note in ignored {
        tracing::info!("{}: {note}", path.display());
    }
    eprintln!(
        "simulating {} robots of {}",
        running.ports.len(),
        path.display()
    );
    Ok(running)
}

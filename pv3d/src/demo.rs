//! The embedded default: `pv3d --demo` simulates stage-worlds/multirobot.world in-process
//! (player-sim as a library) on free local ports and opens configs/multirobot.pv3d.xml against
//! it over real TCP — five robots and their sensors, with nothing else installed.

use std::path::{Path, PathBuf};

use player_sim::serve::{Running, ServeOptions, serve};
use player_sim::served::from_cfg;
use player_sim::sim::Simulation;
use player_sim::world::World;

use crate::composition::Composition;

/// Where the demo's files are: the current directory if it is a checkout, else the checkout
/// this program was built from.
pub fn demo_root() -> PathBuf {
    let here = Path::new("stage-worlds/multirobot.world");
    if here.exists() {
        return PathBuf::from(".");
    }
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// The demo composition.
pub fn composition_file() -> PathBuf {
    demo_root().join("configs/multirobot.pv3d.xml")
}

/// Why the demo world could not start.
#[derive(Debug, thiserror::Error)]
pub enum DemoError {
    #[error(transparent)]
    World(#[from] player_sim::worldfile::WorldFileError),
    #[error("cannot serve the demo world: {0}")]
    Serve(#[from] player_proto::server::ServerError),
}

/// Starts the demo world on free ports and points the composition's Player clients at them.
pub fn start(composition: &mut Composition) -> Result<Running, DemoError> {
    serve_world(
        &demo_root().join("stage-worlds/multirobot.world"),
        composition,
        ServeOptions::default(),
    )
}

/// Serves a Stage world (with the `.cfg` beside it) on free ports and points every Player
/// client of the composition whose port the world configures at the port it got.
pub fn serve_world(
    world_file: &Path,
    composition: &mut Composition,
    options: ServeOptions,
) -> Result<Running, DemoError> {
    let world = World::load(world_file)?;
    let mut ignored = Vec::new();
    let devices = from_cfg(&world_file.with_extension("cfg"), &world, &mut ignored)?;
    for note in ignored {
        tracing::info!("{}: {note}", world_file.display());
    }
    let options = ServeOptions {
        free_ports: true,
        ..options
    };
    let running = serve(Simulation::new(world), devices, options)?;
    for client in &mut composition.clients {
        if let Some(port) = running.port(client.port) {
            client.host = "127.0.0.1".into();
            client.port = port;
        }
    }
    Ok(running)
}

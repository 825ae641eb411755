//! `player-relay --demo` and `--world FILE`: a world served in-process, so that one command
//! shows robots in a browser (`--web`), in Foxglove or in Zenoh with nothing else running.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use anyhow::{Context, Result};
use player_proto::RobotId;
use player_ros2::live::SimClock;
use player_sim::StepObserver;
use player_sim::serve::{Running, ServeOptions, serve_world_file};
use player_sim::sim::Simulation;
use player_sim::world::World;

/// A world served in-process, and its robots as the fronts name them.
pub struct Demo {
    /// One per served port, named after the world's model served there
    /// (`player_relay::world::names`).
    pub robots: Vec<RobotId>,
    /// The world as its file gave it (its walls for the web page).
    pub world: World,
    /// Serves until dropped.
    _running: Running,
}

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

/// Serves the robots of the world at `path` on free local ports; `clock` (ROS 2's `/clock`)
/// is told the simulated time after each step.
pub fn serve(path: &Path, clock: Option<SimClock>) -> Result<Demo> {
    let observer =
        clock.map(|clock| StepObserver(Arc::new(move |sim: &Simulation| clock.set(sim.time))));
    let options = ServeOptions {
        free_ports: true,
        observer,
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
    let world = World::load(path).with_context(|| format!("reading {}", path.display()))?;
    let names = player_relay::world::names(path, &world)
        .with_context(|| format!("reading the .cfg beside {}", path.display()))?;
    let robots = running
        .ports
        .iter()
        .map(|&(configured, port)| {
            let robot = RobotId::new("127.0.0.1", port);
            match names.get(&configured) {
                Some(name) => robot.named(name).unwrap_or_else(|e| {
                    tracing::info!("the robot on port {configured} is shown unnamed: {e}");
                    RobotId::new("127.0.0.1", port)
                }),
                None => robot,
            }
        })
        .collect();
    Ok(Demo {
        robots,
        world,
        _running: running,
    })
}

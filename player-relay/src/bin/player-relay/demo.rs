//! `player-relay --demo` and `--world FILE`: a world served in-process, so that one command
//! shows robots in a browser (`--web`), in Foxglove or in Zenoh with nothing else running.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use player_proto::RobotId;
use player_sim::serve::{Running, ServeOptions, serve_world_file};
use player_sim::served::{Source, devices_beside};
use player_sim::world::World;

/// A world served in-process, and its robots as the fronts name them.
pub struct Demo {
    /// One per served port, named after the world's model served there (see [`names`]).
    pub robots: Vec<RobotId>,
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

/// Serves the robots of the world at `path` on free local ports.
pub fn serve(path: &Path) -> Result<Demo> {
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
    let names = names(path)?;
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
        _running: running,
    })
}

/// The name of the one model whose base (`position2d`) each configured port serves first; a
/// port serving several bases (Stage's one-port worlds) or none of its own (a map, navigation
/// drivers reaching a base through `passthrough`, listed after the base's own .cfg) gives no
/// name: those robots are their servers.
fn names(path: &Path) -> Result<BTreeMap<u16, String>> {
    let world = World::load(path).with_context(|| format!("reading {}", path.display()))?;
    let devices = devices_beside(path, &world, &mut Vec::new())
        .with_context(|| format!("reading the .cfg beside {}", path.display()))?;
    let mut home: BTreeMap<usize, u16> = BTreeMap::new();
    for device in &devices {
        if let Source::Position { robot } = device.source {
            home.entry(robot).or_insert(device.port);
        }
    }
    let mut bases: BTreeMap<u16, Vec<usize>> = BTreeMap::new();
    for (robot, port) in home {
        bases.entry(port).or_default().push(robot);
    }
    Ok(bases
        .into_iter()
        .filter_map(|(port, robots)| match robots.as_slice() {
            [robot] => Some((port, world.robots.get(*robot)?.name.clone())),
            _ => None,
        })
        .collect())
}

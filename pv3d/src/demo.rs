//! The embedded default: `pv3d --demo` simulates stage-worlds/multirobot.world in-process
//! (see [`crate::embedded_world`]) and opens configs/multirobot.pv3d.xml against it over real
//! TCP — five robots and their sensors, with nothing else installed.

use std::path::{Path, PathBuf};

use crate::composition::{Composition, ParserRegistry};

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

/// The demo's world.
pub fn world_file() -> PathBuf {
    demo_root().join("stage-worlds/multirobot.world")
}

/// Every robot's position2d, lasers, sonars, fiducials, cameras and batteries, whatever
/// servers it is given: what `--world` shows of a world with no composition of its own, and
/// `--zenoh` of the robots it finds.
pub fn any_robots_composition_file() -> PathBuf {
    demo_root().join("configs/stage-world.pv3d.xml")
}

/// The composition for a world given with `--world` and no composition: the world's own,
/// `configs/<world>.pv3d.xml`, when there is one that loads (`navigation.world` gets its map,
/// localizer and planner, `classroom.world` its zones; the servers it names are the world's
/// ports, which [`crate::embedded_world::serve_world`] points at wherever they are served);
/// otherwise every robot's position2d, lasers, sonars, fiducials and cameras, on the world's
/// floorplan (`configs/stage-world.pv3d.xml`).
pub fn world_composition_file(world: &Path) -> PathBuf {
    let own = world.file_stem().map(|stem| {
        demo_root()
            .join("configs")
            .join(stem)
            .with_extension("pv3d.xml")
    });
    let loads = |path: &PathBuf| {
        Composition::load_files(std::slice::from_ref(path), &ParserRegistry::standard()).is_ok()
    };
    own.filter(loads)
        .unwrap_or_else(any_robots_composition_file)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_world_with_a_composition_of_its_own_gets_it() {
        let chosen = |world: &str| world_composition_file(&demo_root().join(world));
        assert!(chosen("stage-worlds/navigation.world").ends_with("configs/navigation.pv3d.xml"));
        // It names the world's ports (6665…6672); served on free ones, they are pointed there.
        assert!(chosen("stage-worlds/classroom.world").ends_with("configs/classroom.pv3d.xml"));
        assert!(chosen("stage-worlds/swarm.world").ends_with("configs/stage-world.pv3d.xml"));
    }
}

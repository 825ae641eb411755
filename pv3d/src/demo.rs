//! The embedded default: `pv3d --demo` simulates stage-worlds/multirobot.world in-process
//! (see [`crate::embedded_world`]) and opens configs/multirobot.pv3d.xml against it over real
//! TCP — five robots and their sensors, with nothing else installed.

use std::path::{Path, PathBuf};

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

/// The composition for a world given with `--world` and no composition: every robot's
/// position2d, lasers, sonars, fiducials and cameras, on the world's floorplan.
pub fn world_composition_file() -> PathBuf {
    demo_root().join("configs/stage-world.pv3d.xml")
}

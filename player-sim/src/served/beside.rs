//! The `.cfg` files that run a world when none are named: `<world>.cfg` beside it; then
//! `<world>-sim.cfg`, what only player-sim serves (real Player + Stage 4 would refuse it, so it
//! stays out of the file real Player runs); and, for a world run as Player's two-process
//! navigation setup, `<world>-nav.cfg` (its `passthrough` lines reach the devices of the first).

use std::path::{Path, PathBuf};

use super::{DEFAULT_PORT, ServedDevice, default_devices, from_cfgs};
use crate::world::World;
use crate::worldfile::{Item, WorldFileError, parse_text};

/// The suffix of the file of what only player-sim serves: `navigation-sim.cfg`.
const SIM_SUFFIX: &str = "-sim";
/// The suffix of a navigation half's file name: `navigation.world` → `navigation-nav.cfg`.
const NAV_SUFFIX: &str = "-nav";

/// The `.cfg` files beside `world` that exist, in the order to read them. The others extend
/// the Stage half, so without it none is read.
pub fn cfgs_beside(world: &Path) -> Vec<PathBuf> {
    let stage = world.with_extension("cfg");
    if !stage.exists() {
        return Vec::new();
    }
    let beside = |suffix: &str| {
        world.file_stem().map(|stem| {
            let mut name = stem.to_os_string();
            name.push(suffix);
            world.with_file_name(name).with_extension("cfg")
        })
    };
    std::iter::once(stage)
        .chain(beside(SIM_SUFFIX))
        .chain(beside(NAV_SUFFIX))
        .filter(|p| p.exists())
        .collect()
}

/// The devices `world` (loaded from `world_file`) is served with when nothing else is said:
/// those of the `.cfg` files beside it ([`cfgs_beside`]), else one port per robot from
/// Player's default port. What the files ask that is not simulated goes to `ignored`.
///
/// Files found beside the world were not chosen for it: when they name models the world lacks
/// (Stage's `roomba.cfg` names `roomba0`, `roomba.world` has `r0`; `stage roomba.world` runs
/// without reading it), that is a warning and the world gets one port per robot. A `.cfg`
/// named on purpose is read by [`from_cfgs`], which refuses it.
pub fn devices_beside(
    world_file: &Path,
    world: &World,
    ignored: &mut Vec<String>,
) -> Result<Vec<ServedDevice>, WorldFileError> {
    let cfgs = cfgs_beside(world_file);
    if cfgs.is_empty() {
        return Ok(default_devices(world, DEFAULT_PORT));
    }
    let paths: Vec<&Path> = cfgs.iter().map(PathBuf::as_path).collect();
    let missing = models_missing(&paths, world)?;
    if !missing.is_empty() {
        tracing::warn!(
            "not serving the .cfg beside {}: it names {} that the world lacks; \
             serving one port per robot from {DEFAULT_PORT} instead",
            world_file.display(),
            missing.join(", ")
        );
        return Ok(default_devices(world, DEFAULT_PORT));
    }
    from_cfgs(&paths, world, ignored)
}

/// The models `stage` driver blocks of the files name that are not robots of `world`, each as
/// `"name" (file:line)`.
fn models_missing(paths: &[&Path], world: &World) -> Result<Vec<String>, WorldFileError> {
    let mut missing = Vec::new();
    for path in paths {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path)
            .map_err(|e| WorldFileError::at(&name, 1, 1, format!("cannot read: {e}")))?;
        for item in parse_text(&text, &name)? {
            let Item::Block(block) = item else { continue };
            let is_stage = block.get("name").and_then(|p| p.value.as_str()) == Some("stage");
            let Some(model) = block.get("model").filter(|_| is_stage) else {
                continue;
            };
            let Some(model_name) = model.value.as_str() else {
                continue;
            };
            if !world.robots.iter().any(|r| r.name == model_name) {
                missing.push(format!(
                    "{model_name:?} ({}:{})",
                    model.pos.file, model.pos.line
                ));
            }
        }
    }
    Ok(missing)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_navigation_half_comes_after_the_stage_half() {
        let dir = tempfile::tempdir().unwrap();
        let world = dir.path().join("w.world");
        assert!(cfgs_beside(&world).is_empty());
        std::fs::write(dir.path().join("w-nav.cfg"), "").unwrap();
        assert!(cfgs_beside(&world).is_empty(), "no half to pass through");
        std::fs::write(dir.path().join("w.cfg"), "").unwrap();
        assert_eq!(
            cfgs_beside(&world),
            vec![dir.path().join("w.cfg"), dir.path().join("w-nav.cfg")]
        );
        std::fs::write(dir.path().join("w-sim.cfg"), "").unwrap();
        assert_eq!(
            cfgs_beside(&world),
            vec![
                dir.path().join("w.cfg"),
                dir.path().join("w-sim.cfg"),
                dir.path().join("w-nav.cfg")
            ]
        );
    }
}

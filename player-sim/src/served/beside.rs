//! The `.cfg` files that run a world when none are named: `<world>.cfg` beside it, and, for a
//! world run as Player's two-process navigation setup, `<world>-nav.cfg` after it (its
//! `passthrough` lines reach the devices of the first).

use std::path::{Path, PathBuf};

/// The suffix of a navigation half's file name: `navigation.world` → `navigation-nav.cfg`.
const NAV_SUFFIX: &str = "-nav";

/// The `.cfg` files beside `world` that exist, in the order to read them.
pub fn cfgs_beside(world: &Path) -> Vec<PathBuf> {
    let stage = world.with_extension("cfg");
    let nav = world
        .file_stem()
        .map(|stem| {
            let mut name = stem.to_os_string();
            name.push(NAV_SUFFIX);
            world.with_file_name(name).with_extension("cfg")
        })
        .filter(|_| stage.exists());
    std::iter::once(stage)
        .chain(nav)
        .filter(|p| p.exists())
        .collect()
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
    }
}

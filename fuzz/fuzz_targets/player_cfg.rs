//! A Player `.cfg` as a person writes it, read against navigation.world (its robots, its map
//! and planner drivers): the devices it serves, or an error naming `fuzz.cfg` and where in it —
//! never a panic, and never an allocation sized by a number in the file without a bound.
#![no_main]

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use libfuzzer_sys::fuzz_target;
use player_sim::served::from_cfg;
use player_sim::world::World;

/// This process's scratch `.cfg`, in a folder that sees the shipped worlds' bitmaps as its
/// own (a `.cfg` names its map images relative to itself), and the world it is read against.
fn scratch() -> &'static (PathBuf, World) {
    static SCRATCH: OnceLock<(PathBuf, World)> = OnceLock::new();
    SCRATCH.get_or_init(|| {
        let worlds = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds");
        let dir = std::env::temp_dir().join(format!("pv3d-fuzz-cfg-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let bitmaps = dir.join("bitmaps");
        if !bitmaps.exists() {
            std::os::unix::fs::symlink(worlds.join("bitmaps"), &bitmaps).unwrap();
        }
        let world = World::load(&worlds.join("navigation.world")).expect("navigation.world");
        (dir.join("fuzz.cfg"), world)
    })
}

fuzz_target!(|data: &[u8]| {
    let (path, world) = scratch();
    std::fs::write(path, data).unwrap();
    let mut ignored = Vec::new();
    if let Err(e) = from_cfg(path, world, &mut ignored) {
        let text = e.to_string();
        assert!(text.contains("fuzz.cfg"), "{text}");
    }
});

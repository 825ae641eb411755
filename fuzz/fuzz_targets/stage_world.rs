//! A Stage world file as a person writes it: loaded into a world (models, floorplans drawn
//! into the ray grid, people) or refused with `file:line:col` — never a panic, and never an
//! allocation sized by a number in the file without a bound (libFuzzer's memory limit
//! catches one).
#![no_main]

use std::io::Write;
use std::sync::OnceLock;

use libfuzzer_sys::fuzz_target;
use player_sim::world::World;

/// This process's scratch file: the loader reads files (worlds include others).
fn scratch() -> &'static std::path::Path {
    static PATH: OnceLock<std::path::PathBuf> = OnceLock::new();
    PATH.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("pv3d-fuzz-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir.join("fuzz.world")
    })
}

fuzz_target!(|data: &[u8]| {
    let path = scratch();
    std::fs::File::create(path).unwrap().write_all(data).unwrap();
    if let Err(e) = World::load(path) {
        let text = e.to_string();
        assert!(text.contains("fuzz.world:") || text.contains("fuzz.world"), "{text}");
    }
});

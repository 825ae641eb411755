//! A world's `speedup` is read (player-sim runs at it headless unless `--speedup` is given).

use player_sim::world::World;

fn speedup_of(text: &str) -> Option<f64> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("w.world");
    std::fs::write(&path, text).unwrap();
    World::load(&path).unwrap().speedup
}

#[test]
fn a_worlds_speedup_is_read() {
    assert_eq!(speedup_of("speedup 0\n"), Some(0.0));
    assert_eq!(speedup_of("speedup -1\n"), Some(-1.0));
    assert_eq!(speedup_of("interval_sim 100\nspeedup 4.5\n"), Some(4.5));
    assert_eq!(speedup_of("interval_sim 100\n"), None);
}

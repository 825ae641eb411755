//! World files refused or warned about where the fault is written (file:line:col): includes
//! that cannot be found, syntax errors, parts outside what player-sim reads, cameras that
//! cannot render.

mod support;

use std::path::{Path, PathBuf};

use player_sim::world::World;
use support::write;

#[test]
fn the_reference_world_names_its_missing_include() {
    // The world the repository's captures were recorded in (`captures/world/`).
    let reference = std::env::var_os("PLAYER_CAPTURES_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../captures"))
        .join("world/ref3.world");
    assert!(
        reference.is_file(),
        "missing world file {}",
        reference.display()
    );
    let err = World::load(&reference).unwrap_err().to_string();
    assert!(
        err.contains("ref3.world:3:1: cannot include") && err.contains("pioneer.inc"),
        "{err}"
    );
}

#[test]
fn syntax_errors_and_unsupported_parts_are_reported_with_positions() {
    let dir = tempfile::tempdir().unwrap();
    let bad = write(
        dir.path(),
        "bad.world",
        "interval_sim 100\nposition( name \"r\" pose [ 0 0 0 \n",
    );
    assert!(
        World::load(&bad)
            .unwrap_err()
            .to_string()
            .starts_with(&format!("{}:2:", bad.display()))
    );
    let odd = write(
        dir.path(),
        "odd.world",
        "window ( size [ 1 1 ] )\nlaser_max 3\npaused 1\nresolution 0.05\n\
         position( name \"r\" gui_nose 1 blinkenlight( ) sensor( range [ 0 1 ] ) )\n",
    );
    let world = World::load(&odd).unwrap();
    let notes = world.ignored.join("\n");
    assert!(
        notes.contains("ignored: window (the Stage GUI) at"),
        "{notes}"
    );
    assert!(
        notes.contains("ignored: world property laser_max at"),
        "{notes}"
    );
    assert!(
        notes.contains("ignored: position property gui_nose at"),
        "{notes}"
    );
    assert!(
        notes.contains("ignored: a blinkenlight's light (its body is solid) at"),
        "{notes}"
    );
    assert!(
        notes.contains("ignored: sensor() in position at"),
        "{notes}"
    );
    assert!(
        notes.contains("ignored: world property paused (player-sim has no GUI")
            && notes.contains("odd.world:3"),
        "{notes}"
    );
    assert!(
        notes.contains("ignored: world property resolution (only block floorplans")
            && notes.contains("odd.world:4"),
        "{notes}"
    );
    let pointless = write(
        dir.path(),
        "pointless.world",
        "model( name \"m\"\n  block( points 3 point[0] [ 0 0 ] ) )\n",
    );
    let e = World::load(&pointless).unwrap_err().to_string();
    assert!(
        e.starts_with(&format!("{}:2:", pointless.display())) && e.contains("no point[1]"),
        "{e}"
    );
    let unknown = write(dir.path(), "unknown.world", "pioneer( name \"x\" )\n");
    assert!(
        World::load(&unknown)
            .unwrap_err()
            .to_string()
            .contains("unknown model type \"pioneer\"")
    );
}

#[test]
fn camera_resolutions_and_fields_of_view_that_cannot_render_are_refused_where_written() {
    let dir = tempfile::tempdir().unwrap();
    for (camera, what) in [
        ("resolution [ 4096 4096 ]", "camera resolution 4096 x 4096"),
        ("resolution [ 0 120 ]", "camera resolution 0 x 120"),
        ("fov [ 200 40 ]", "camera fov"),
    ] {
        let path = write(
            dir.path(),
            "cam.world",
            &format!("position( name \"r\"\n  camera( {camera} ) )\n"),
        );
        let err = World::load(&path).unwrap_err().to_string();
        assert!(
            err.starts_with(&format!("{}:2:", path.display())) && err.contains(what),
            "{err}"
        );
    }
    let path = write(
        dir.path(),
        "cam.world",
        "position( name \"r\" camera( resolution [ 320 240 ] fov [ 90 60 ] ) )\n",
    );
    let camera = &World::load(&path).unwrap().robots[0].cameras[0];
    assert_eq!((camera.width_px, camera.height_px), (320, 240));
}

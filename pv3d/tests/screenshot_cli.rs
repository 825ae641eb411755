//! `pv3d --screenshot` end to end: the binary loads a composition, runs it offscreen and writes
//! a PNG whose pixels show what the composition says.

mod support;

use std::path::Path;

use support::{count, laser_pixels, pv3d, robot_pixels, run_ok, screenshot, wall_pixels};

#[test]
fn a_ground_and_grid_composition_is_drawn_with_its_axes() {
    let dir = tempfile::tempdir().unwrap();
    let composition = dir.path().join("ground.xml");
    std::fs::write(
        &composition,
        r#"<pv3d>
  <plugin library="libpv3d_lights"><background>#101820</background></plugin>
  <plugin library="libpv3d_ground"/>
  <plugin library="libpv3d_grid"/>
</pv3d>"#,
    )
    .unwrap();
    let png = dir.path().join("shot.png");
    let out = pv3d()
        .arg(&composition)
        .args([
            "--headless",
            "--after",
            "0.1",
            "--size",
            "640x400",
            "--screenshot",
        ])
        .arg(&png)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let image = image::open(&png).unwrap().to_rgba8();
    assert_eq!(image.dimensions(), (640, 400));
    // The 3D view fills the space right of the item tree; its centre is the world origin,
    // where the red x axis runs horizontally and the green y axis vertically.
    let (x0, x1) = (image.width() / 2, image.width());
    let view_centre_x = (230 + x1) / 2;
    let row = image.height() / 2;
    let red_on_row = (x0..x1).any(|x| {
        let p = image.get_pixel(x, row);
        p[0] > 140 && p[1] < 100
    });
    // Lines are one pixel wide; allow for rounding of the panel's edge.
    let green_in_column = (view_centre_x - 3..=view_centre_x + 3).any(|x| {
        (0..image.height())
            .filter(|&y| {
                let p = image.get_pixel(x, y);
                p[1] > 130 && p[0] < 100
            })
            .count()
            > image.height() as usize / 2
    });
    assert!(red_on_row, "x axis drawn across the middle row");
    assert!(green_in_column, "y axis drawn down the middle column");
}

#[test]
fn a_broken_composition_fails_with_file_line_col() {
    let dir = tempfile::tempdir().unwrap();
    let composition = dir.path().join("broken.xml");
    std::fs::write(&composition, "<pv3d>\n  <plugin librar=\"x\"/>\n</pv3d>").unwrap();
    let out = pv3d()
        .arg(&composition)
        .args(["--headless", "--screenshot"])
        .arg(dir.path().join("never.png"))
        .output()
        .unwrap();
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("broken.xml:2:11: unknown attribute librar"),
        "{stderr}"
    );
}

#[test]
fn emit_config_writes_a_loadable_composition() {
    let dir = tempfile::tempdir().unwrap();
    let out_file = dir.path().join("emitted.xml");
    let configs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs/single-laser.pv3d.xml");
    let out = pv3d()
        .arg(&configs)
        .arg("--emit-config")
        .arg(&out_file)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let emitted = std::fs::read_to_string(&out_file).unwrap();
    assert!(
        emitted.contains("<playerClient host=\"localhost\" port=\"6665\"/>"),
        "{emitted}"
    );
    assert!(emitted.contains("libpv3d_ground"), "{emitted}");
}

#[test]
fn the_demo_shows_the_arena_robots_and_their_lasers() {
    let dir = tempfile::tempdir().unwrap();
    let image = screenshot(&["--demo"], "2.5", "1000x700", &dir.path().join("demo.png"));
    let (walls, robots, lasers) = (
        wall_pixels(&image),
        robot_pixels(&image),
        laser_pixels(&image),
    );
    assert!(walls > 3000, "the arena's walls: {walls} pixels");
    assert!(robots > 5 * 40, "five robot bodies: {robots} pixels");
    assert!(lasers > 300, "laser returns: {lasers} pixels");
}

#[test]
fn the_plugins_state_is_written_back_on_exit() {
    let dir = tempfile::tempdir().unwrap();
    let saved = dir.path().join("session.pv3d.xml");
    let out = pv3d()
        .args([
            "--demo",
            "--headless",
            "--after",
            "0.5",
            "--size",
            "640x400",
            "--screenshot",
        ])
        .arg(dir.path().join("s.png"))
        .arg("--save-to")
        .arg(&saved)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&saved).unwrap();
    // Handlers were applied: one plugin per device, each with its state written in.
    assert_eq!(
        text.matches("library=\"libpv3d_position2d\"").count(),
        5,
        "{text}"
    );
    assert!(
        text.contains("<maxSpeed>0.5</maxSpeed>")
            && text.contains("<trailLength>200</trailLength>"),
        "{text}"
    );
    assert!(
        text.contains("<drawPoints>1</drawPoints>")
            && text.contains("<fillLaserCspace>1</fillLaserCspace>"),
        "{text}"
    );
    let reloaded =
        pv3d::composition::Composition::load(&saved, &pv3d::composition::ParserRegistry::default())
            .unwrap();
    assert_eq!(reloaded.plugins.len(), text.matches("<plugin ").count());
}

#[test]
fn any_stage_world_is_shown_with_its_floorplan_and_every_robot() {
    let dir = tempfile::tempdir().unwrap();
    let emitted = dir.path().join("classroom.xml");
    let image = screenshot(
        &["--world", "stage-worlds/classroom.world"],
        "1.5",
        "1000x700",
        &dir.path().join("classroom.png"),
    );
    let (walls, robots) = (wall_pixels(&image), robot_pixels(&image));
    assert!(
        walls > 3000,
        "the room's walls, from the world's floorplan: {walls} pixels"
    );
    assert!(robots > 8 * 20, "eight robot bodies: {robots} pixels");

    // The composition it made: a client per served port, one robot plugin each.
    run_ok(
        pv3d()
            .args(["--world", "stage-worlds/classroom.world", "--emit-config"])
            .arg(&emitted),
    );
    let text = std::fs::read_to_string(&emitted).unwrap();
    assert_eq!(text.matches("<playerClient ").count(), 8, "{text}");
    assert_eq!(text.matches("libpv3d_position2d").count(), 8, "{text}");
    assert!(
        text.contains("room.png"),
        "the ground got the floorplan: {text}"
    );
}

#[test]
fn no_display_and_no_screenshot_says_what_to_do() {
    let out = pv3d()
        .arg("--demo")
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .unwrap();
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("no display"), "{stderr}");
    assert!(stderr.contains("--screenshot"), "{stderr}");
}

#[test]
fn a_world_drawn_with_blocks_shows_its_block_walls() {
    let dir = tempfile::tempdir().unwrap();
    let image = screenshot(
        &["--world", "stage-worlds/blocks.world"],
        "0.5",
        "800x600",
        &dir.path().join("blocks.png"),
    );
    // The walls' lit tops, in the ground's wall grey.
    let walls = wall_pixels(&image);
    assert!(walls > 5000, "the block room's walls: {walls} pixels");
    // The red triangular crate, an obstacle drawn with a block of its own.
    let crate_pixels = count(&image, |p| p[0] > 120 && p[1] < 60 && p[2] < 60);
    assert!(crate_pixels > 300, "the crate: {crate_pixels} pixels");
}

#[test]
fn the_view_can_start_in_perspective() {
    let dir = tempfile::tempdir().unwrap();
    // Where the room's walls begin on the left, in the wall rows nearest the top and the
    // bottom of the picture: the same for a map, further in at the far side in perspective.
    let left_edges = |view: &str| {
        let image = screenshot(
            &["--world", "stage-worlds/classroom.world", "--view", view],
            "1.0",
            "900x700",
            &dir.path().join(format!("{view}.png")),
        );
        let is_wall = |p: &image::Rgba<u8>| {
            (130..=175).contains(&p[0])
                && (i32::from(p[0]) - i32::from(p[2])).abs() < 20
                && (i32::from(p[0]) - i32::from(p[1])).abs() < 12
        };
        // Right of the item tree, above the status panel.
        let rows: Vec<(u32, u32)> = (0..560)
            .filter_map(|y| {
                let x = (330..image.width()).find(|&x| is_wall(image.get_pixel(x, y)))?;
                Some((y, x))
            })
            .collect();
        assert!(
            rows.len() > 100,
            "{view}: the room shows ({} rows)",
            rows.len()
        );
        (rows[2].1, rows[rows.len() - 3].1)
    };
    let (top_far, top_near) = left_edges("top");
    assert!(
        top_far.abs_diff(top_near) <= 4,
        "a map: {top_far} vs {top_near}"
    );
    let (far, near) = left_edges("perspective");
    assert!(
        far > near + 20,
        "perspective: far side {far} right of near side {near}"
    );
}

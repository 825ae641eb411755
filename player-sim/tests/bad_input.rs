//! Bad world files are refused with where the fault is written (file:line), never a hang, a
//! crash or an allocation the file's numbers ask for: floorplan bitmaps missing, truncated, not
//! images, empty or claiming absurd sizes; resolutions and sizes of nothing or less; a define
//! that is its own base. A world of 100 000 models is no fault: it loads and steps.

mod support;

use std::path::Path;

use player_sim::sim::Simulation;
use player_sim::world::World;
use support::write;

/// The error loading `text` (written as `bad.world` in `dir`) gives.
fn refused(dir: &Path, text: &str) -> String {
    let path = write(dir, "bad.world", text);
    match World::load(&path) {
        Ok(_) => panic!("loaded: {text}"),
        Err(e) => e.to_string(),
    }
}

/// A floorplan on line 2 whose bitmap is `bitmap`.
fn floorplan(bitmap: &str) -> String {
    format!("\nmodel( name \"map\" size [ 10 10 1 ]\n bitmap \"{bitmap}\" )\n")
}

/// The bytes of a PNG whose header says `width` x `height`, 8-bit grey, with no pixels.
fn png_header(width: u32, height: u32) -> Vec<u8> {
    let mut ihdr = b"IHDR".to_vec();
    ihdr.extend(width.to_be_bytes());
    ihdr.extend(height.to_be_bytes());
    ihdr.extend([8, 0, 0, 0, 0]);
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    png.extend(13u32.to_be_bytes());
    png.extend(&ihdr);
    png.extend(crc32(&ihdr).to_be_bytes());
    // One empty data chunk: the header is all a reader needs before the pixels.
    png.extend(0u32.to_be_bytes());
    png.extend(b"IDAT");
    png.extend(crc32(b"IDAT").to_be_bytes());
    png
}

/// PNG's CRC-32 (so that the header is read as valid and its sizes are believed).
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = 0xFFFF_FFFFu32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

/// A real 20 x 20 PNG with a wall across it.
fn good_png(dir: &Path) -> Vec<u8> {
    let mut image = image::GrayImage::from_pixel(20, 20, image::Luma([255]));
    for x in 0..20 {
        image.put_pixel(x, 10, image::Luma([0]));
    }
    let path = dir.join("good.png");
    image.save(&path).unwrap();
    std::fs::read(path).unwrap()
}

#[test]
fn bitmaps_missing_or_corrupt_are_refused_where_named() {
    let dir = tempfile::tempdir().unwrap();
    let good = good_png(dir.path());
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        (
            "truncated.png",
            good[..good.len() / 2].to_vec(),
            "cannot read bitmap",
        ),
        (
            "text.png",
            b"this is not an image at all\n".to_vec(),
            "cannot read bitmap",
        ),
        ("empty.png", Vec::new(), "cannot read bitmap"),
        ("zero.png", png_header(0, 0), "cannot read bitmap"),
        (
            "wide.png",
            png_header(2_000_000_000, 2_000_000_000),
            "cannot read bitmap",
        ),
        // A size PNG allows but no floorplan needs: refused before any pixel is read.
        (
            "big.png",
            png_header(100_000, 100_000),
            "more than the 67108864",
        ),
    ];
    for (name, bytes, says) in cases {
        std::fs::write(dir.path().join(name), bytes).unwrap();
        let e = refused(dir.path(), &floorplan(name));
        assert!(
            e.contains("bad.world:3:") && e.contains(says),
            "{name}: {e}"
        );
    }
    let e = refused(dir.path(), &floorplan("nowhere.png"));
    assert!(
        e.contains("bad.world:3:") && e.contains("nowhere.png"),
        "{e}"
    );
    // The good one loads.
    std::fs::write(dir.path().join("fine.png"), good).unwrap();
    let world = World::load(&write(dir.path(), "fine.world", &floorplan("fine.png"))).unwrap();
    assert!(world.floor.is_some());
}

#[test]
fn resolutions_and_sizes_of_nothing_or_less_are_refused_where_written() {
    let dir = tempfile::tempdir().unwrap();
    for (text, says) in [
        ("\nresolution 0\n", "resolution must be a positive number"),
        (
            "\nresolution -0.02\n",
            "resolution must be a positive number",
        ),
        (
            "position( name \"r\"\n size [ -0.4 0.4 0.2 ] )\n",
            "must be finite and not negative",
        ),
        (
            "model( name \"box\"\n size [ 1 1 -1 ] )\n",
            "must be finite and not negative",
        ),
        (
            "position( name \"r\" ranger( sensor( range [ 0 5 ] ) )\n model( size [ 0.1 -0.1 0.1 ] ) )\n",
            "must be finite and not negative",
        ),
        (
            "model( name \"map\" bitmap \"x.png\"\n size [ 0 10 1 ] )\n",
            "a floorplan's size [0 10] must be more than nothing",
        ),
        (
            "floorplan( name \"map\" block( points 3 point[0] [ 0 0 ] point[1] [ 1 0 ] point[2] [ 0 1 ] )\n size [ 10 -10 1 ] )\n",
            "must be more than nothing",
        ),
    ] {
        let e = refused(dir.path(), text);
        assert!(
            e.contains("bad.world:2:") && e.contains(says),
            "{text}: {e}"
        );
    }
}

#[test]
fn a_define_that_is_its_own_base_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let e = refused(dir.path(), "\ndefine loop loop ( )\nloop( )\n");
    assert!(e.contains("loop is defined through itself"), "{e}");
}

#[test]
fn a_world_of_a_hundred_thousand_models_loads_and_steps() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("define crate model ( size [ 0.2 0.2 0.2 ] )\n");
    for k in 0..100_000 {
        // Each with a property player-sim ignores, so that as many notes are made.
        text += &format!(
            "crate( name \"c{k}\" pose [ {} {} 0 0 ] gui_nose 1 )\n",
            (k % 400) as f64 * 0.5,
            (k / 400) as f64 * 0.5
        );
    }
    text += "position( name \"r\" pose [ -2 -2 0 0 ] ranger( sensor( range [ 0 8 ] fov 180 samples 181 ) ) )\n";
    let path = write(dir.path(), "crowd.world", &text);
    let world = World::load(&path).unwrap();
    assert_eq!(world.obstacles.len(), 100_000);
    assert_eq!(world.ignored.len(), 100_000, "a note for each, said once");
    let mut sim = Simulation::new(world);
    sim.robots[0].command = player_sim::sim::Command::Velocity {
        vx: 0.3,
        vy: 0.0,
        va: 0.0,
    };
    for _ in 0..5 {
        sim.step();
    }
    assert!(sim.robots[0].pose.x > -2.0);
}

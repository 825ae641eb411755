//! Every example composition in configs/, run against the Stage world it was written for
//! (simulated in-process) and screenshotted offscreen: what each promises is on the picture.

use std::path::Path;
use std::process::Command;

use image::{Rgba, RgbaImage};

fn screenshot(world: &str, composition: &str, dir: &Path) -> RgbaImage {
    let png = dir.join(format!("{}.png", composition.replace('/', "_")));
    let out = Command::new(env!("CARGO_BIN_EXE_pv3d"))
        .args(["--world", world, composition, "--headless"])
        .args(["--after", "1.5", "--size", "1000x700", "--screenshot"])
        .arg(&png)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{composition}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("ERROR"), "{composition}: {stderr}");
    image::open(&png).unwrap().to_rgba8()
}

fn count(image: &RgbaImage, test: impl Fn(&Rgba<u8>) -> bool) -> usize {
    image.pixels().filter(|p| test(p)).count()
}

/// The body colour position2d draws robots in (a blue), as the demo test counts it.
fn robot_pixels(image: &RgbaImage) -> usize {
    count(image, |p| {
        p[2] > 150 && p[0] < 110 && p[1] > 90 && p[1] < 190
    })
}

fn laser_pixels(image: &RgbaImage) -> usize {
    count(image, |p| {
        p[0] > 200 && (70..=120).contains(&p[1]) && p[2] < 90
    })
}

#[test]
fn each_example_composition_shows_what_it_promises() {
    let dir = tempfile::tempdir().unwrap();

    let single = screenshot(
        "stage-worlds/simple.world",
        "configs/single-laser.pv3d.xml",
        dir.path(),
    );
    assert!(
        robot_pixels(&single) > 20,
        "one robot: {}",
        robot_pixels(&single)
    );
    assert!(
        laser_pixels(&single) > 100,
        "its laser: {}",
        laser_pixels(&single)
    );

    // The paper's example: three of the world's five robots, with sonar cones.
    let teleop = screenshot(
        "stage-worlds/multirobot.world",
        "configs/stage-teleop.pv3d.xml",
        dir.path(),
    );
    assert!(
        robot_pixels(&teleop) > 40,
        "three robots: {}",
        robot_pixels(&teleop)
    );
    let cones = count(&teleop, |p| {
        let [r, g, b, _] = p.0.map(i32::from);
        g > r + 20 && b > r + 10 && g > 120
    });
    assert!(cones > 2000, "sonar cones: {cones}");
    let emitted = dir.path().join("teleop.xml");
    let out = Command::new(env!("CARGO_BIN_EXE_pv3d"))
        .args([
            "--world",
            "stage-worlds/multirobot.world",
            "configs/stage-teleop.pv3d.xml",
        ])
        .arg("--emit-config")
        .arg(&emitted)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&emitted).unwrap();
    assert_eq!(text.matches("libpv3d_position2d").count(), 3, "{text}");
    assert_eq!(text.matches("<playerClient ").count(), 3, "{text}");

    // The camera window: the simulated sky above the horizon.
    let camera = screenshot(
        "stage-worlds/multirobot.world",
        "configs/camera.pv3d.xml",
        dir.path(),
    );
    let sky = count(&camera, |p| {
        p[2] > 200 && p[1] > 150 && p[0] < 170 && p[0] > 60
    });
    assert!(sky > 2000, "the camera's picture (sky pixels): {sky}");

    // Eight robots, and the zones' colours.
    let classroom = screenshot(
        "stage-worlds/classroom.world",
        "configs/classroom.pv3d.xml",
        dir.path(),
    );
    assert!(
        robot_pixels(&classroom) > 8 * 20,
        "eight robots: {}",
        robot_pixels(&classroom)
    );
    let charging = count(&classroom, |p| {
        let [r, g, b, _] = p.0.map(i32::from);
        g > r + 25 && g > b + 10 && g > 90
    });
    assert!(charging > 1000, "the green charging zone: {charging}");
}

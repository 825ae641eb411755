//! Every example composition in configs/, run against the Stage world it was written for
//! (simulated in-process) and screenshotted offscreen: what each promises is on the picture.

mod support;

use std::path::Path;

use support::{count, laser_pixels, pv3d, robot_pixels, run_ok};

fn screenshot(world: &str, composition: &str, dir: &Path) -> image::RgbaImage {
    let png = dir.join(format!("{}.png", composition.replace('/', "_")));
    support::screenshot(&["--world", world, composition], "1.5", "1000x700", &png)
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
    run_ok(
        pv3d()
            .args(["--world", "stage-worlds/multirobot.world"])
            .args(["configs/stage-teleop.pv3d.xml", "--emit-config"])
            .arg(&emitted),
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

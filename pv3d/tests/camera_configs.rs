//! The compositions of virtual cameras and formulas, run against simple.world and
//! screenshotted offscreen: the frustums, the cameras' windows and the typeset formula are on
//! the picture.

mod support;

/// Where the 3-D view begins (right of the item tree) and ends (above the status lines), and
/// the middle row of the window, at the 1000 × 700 screenshot size.
const VIEW_LEFT: u32 = 310;
const LOWER_HALF: u32 = 400;
const STATUS_TOP: u32 = 650;
/// Left of the embedded camera windows, at the same size.
const WINDOWS_LEFT: u32 = 675;

use support::count;

fn screenshot(composition: &str, dir: &std::path::Path) -> image::RgbaImage {
    let png = dir.join(format!("{}.png", composition.replace('/', "_")));
    support::screenshot(
        &["--world", "stage-worlds/simple.world", composition],
        "1.5",
        "1000x700",
        &png,
    )
}

#[test]
fn virtual_cameras_show_their_frustums_and_windows() {
    let dir = tempfile::tempdir().unwrap();
    let image = screenshot("configs/virtual-camera.pv3d.xml", dir.path());
    // The onboard camera's frustum in its default #ffd040, the corner's in #40d0ff.
    let onboard = count(&image, |p| {
        p[0] > 220 && (180..=230).contains(&p[1]) && p[2] < 110
    });
    let corner = count(&image, |p| p[0] < 110 && p[1] > 180 && p[2] > 220);
    assert!(onboard > 50, "onboard frustum: {onboard}");
    assert!(corner > 50, "corner frustum: {corner}");
    // The corner camera sees the robot: its blue body appears twice (the view and the window).
    let robot = support::robot_pixels(&image);
    assert!(
        robot > 40,
        "robot in the view and the corner camera's window: {robot}"
    );
}

#[test]
fn the_formula_stands_next_to_the_robot() {
    let dir = tempfile::tempdir().unwrap();
    let image = screenshot("configs/formulas.pv3d.xml", dir.path());
    // v = ωr in #ffe070.
    let ink = count(&image, |p| {
        p[0] > 200 && p[1] > 180 && (60..=160).contains(&p[2])
    });
    assert!(ink > 80, "the yellow formula: {ink}");
    // The white formula on the floor, in the lower half of the view (the panel's text and the
    // robot's name lie elsewhere).
    let white = image
        .enumerate_pixels()
        .filter(|(x, y, p)| {
            *x > VIEW_LEFT
                && (LOWER_HALF..STATUS_TOP).contains(y)
                && p.0[..3].iter().all(|&c| c > 200)
        })
        .count();
    assert!(white > 60, "the white formula: {white}");
}

#[test]
fn a_filtered_camera_window_shows_edges() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("camera-filtered.png");
    let image = support::screenshot(
        &[
            "--world",
            "stage-worlds/multirobot.world",
            "configs/camera-filtered.pv3d.xml",
        ],
        "2",
        "1000x700",
        &png,
    );
    // The camera windows stand at the right of the view; through Sobel edges a camera frame is
    // black but for thin white outlines, where the raw frame is grey walls and floor.
    let in_windows = |p: &(u32, u32, &image::Rgba<u8>)| p.0 > WINDOWS_LEFT;
    let black = image
        .enumerate_pixels()
        .filter(|p| in_windows(p) && p.2.0[..3].iter().all(|&c| c < 12))
        .count();
    let white = image
        .enumerate_pixels()
        .filter(|p| in_windows(p) && p.2.0[..3].iter().all(|&c| c > 230))
        .count();
    assert!(black > 10_000, "black between the edges: {black}");
    assert!(white > 300, "white edges: {white}");
}

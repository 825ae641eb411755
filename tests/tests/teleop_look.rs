//! The paper's three-robot tele-operation composition (configs/stage-teleop.pv3d.xml) drawn
//! offscreen through the viewer's own UI, close up on robot r0: its rover skin
//! (configs/skins/rover.obj) is drawn, not the box; its controls show over the view while it is
//! selected, and the popup of its actions on another robot opens, as does the popup of its
//! "Go to point…" service. The pictures are saved for people to look at
//! (target/tmp/teleop_close.png, teleop_perspective.png, teleop_service_popup.png) and the skin's pixels checked.

use std::time::{Duration, Instant};

use framework::scene::NodeId;
use glam::Vec3;
use pv3d::headless::HeadlessUi;
use tests::{load, run_for, serve, sim_pose, viewer_for};

fn robot_near(viewer: &pv3d::app::Viewer, x: f64, y: f64) -> NodeId {
    let scene = viewer.scene();
    scene
        .iter()
        .filter(|(_, o)| o.has_tag("robot"))
        .map(|(id, _)| (id, Vec3::from(scene.world_transform(id).translation)))
        .min_by(|a, b| {
            let d = |p: Vec3| (f64::from(p.x) - x).hypot(f64::from(p.y) - y);
            d(a.1).total_cmp(&d(b.1))
        })
        .expect("robots drawn")
        .0
}

#[test]
fn the_teleop_composition_wears_rover_skins_and_shows_controls_and_popups() {
    let mut composition = load(&["configs/stage-teleop.pv3d.xml"]);
    let running = serve("stage-worlds/multirobot.world", &mut composition, 1.0);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    run_for(&mut viewer, Duration::from_millis(500));

    let mut ui = HeadlessUi::new(1000, 700).expect("headless GL (Mesa EGL)");
    // A few frames to let the view frame the arena, then close up on r0, from above.
    for _ in 0..3 {
        viewer.update(Instant::now());
        ui.run(|ui| viewer.ui(ui));
    }
    let r0 = sim_pose(&running, 0);
    let r1 = sim_pose(&running, 1);
    viewer.view.camera.centre = Vec3::new(r0.0 as f32, r0.1 as f32, 0.0);
    viewer.view.camera.distance = 2.0;
    let node = robot_near(&viewer, r0.0, r0.1);
    viewer.click(Some(node), None);
    assert!(viewer.active_title().is_some(), "r0 selected");
    viewer.secondary_click(Some(robot_near(&viewer, r1.0, r1.1)));
    assert_eq!(viewer.popup_actions(), Some(vec!["Go to", "Follow"]));
    for _ in 0..3 {
        viewer.update(Instant::now());
        ui.run(|ui| viewer.ui(ui));
    }
    let image = ui.read_pixels();
    let out = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("teleop_close.png");
    image.save(&out).unwrap();

    // The body's blue (#3c8cdc, lit) fills a good part of the view's middle: the rover is
    // drawn large. Its wheels stick out beyond the deck, so its shape is no box: count the
    // blue in the middle column and row.
    let blue = |p: &[u8; 4]| p[2] > 120 && u16::from(p[2]) > u16::from(p[0]) + 60 && p[1] > p[0];
    let (w, h) = image.dimensions();
    let (cx, cy) = (230 + (w - 230) / 2, (h - 140) / 2);
    let mut count = 0;
    for y in cy - 120..cy + 120 {
        for x in cx - 120..cx + 120 {
            if blue(&image.get_pixel(x, y).0) {
                count += 1;
            }
        }
    }
    assert!(
        count > 5_000,
        "r0's body should fill the view's middle: {count} blue pixels ({})",
        out.display()
    );

    // The same robot in perspective, from the side and above: wheels, nose and deck.
    viewer.close_popup();
    viewer.view.camera.toggle_projection();
    viewer.view.camera.orbit(0.6, -0.5);
    viewer.view.camera.distance = 1.6;
    for _ in 0..2 {
        viewer.update(Instant::now());
        ui.run(|ui| viewer.ui(ui));
    }
    ui.read_pixels()
        .save(out.with_file_name("teleop_perspective.png"))
        .unwrap();
    viewer.view.camera.toggle_projection();

    // The item tree's "Go to point…" opens its popup (drawn; saved beside the other picture).
    let active = viewer.active_title().unwrap();
    let index = viewer.titles().iter().position(|t| *t == active).unwrap();
    assert!(viewer.use_service(index, "Go to point…"));
    assert_eq!(
        viewer.popup_title(),
        Some(format!("{active}: Go to point…"))
    );
    for _ in 0..2 {
        viewer.update(Instant::now());
        ui.run(|ui| viewer.ui(ui));
    }
    ui.read_pixels()
        .save(out.with_file_name("teleop_service_popup.png"))
        .unwrap();
    assert!(!viewer.use_service(index, "Fly"), "no such service");
}

//! The navigation composition's robot components end to end against player-sim over TCP:
//! r2 of stage-worlds/navigation.world has a blobfinder and a gripper with a red puck between
//! its paddles. The blobfinder's window lists the blobs it sees; the gripper's paddles stand
//! in front of r2 and close when its "Close" service is used. (Localize and planner are not
//! served by player-sim yet: their plugins are tested against fed messages in `plugins/`.)

use std::time::Duration;

use pv3d::app::Viewer;
use tests::{load, run_until, serve, texts_drawn, viewer_for};

const PATIENCE: Duration = Duration::from_secs(20);

/// How far apart the gripper's paddles' outer faces are, once it is drawn below its robot.
fn paddle_spread(viewer: &Viewer) -> Option<f32> {
    let scene = viewer.scene();
    let (_, gripper) = scene
        .iter()
        .find(|(_, o)| o.has_tag("gripper") && o.parent.is_some())?;
    let ys = gripper.geometry.mesh.iter().map(|v| v.pos.y);
    let spread = ys.clone().fold(f32::MIN, f32::max) - ys.fold(f32::MAX, f32::min);
    (spread.is_finite() && spread > 0.0).then_some(spread)
}

#[test]
fn r2s_blobs_are_listed_and_its_gripper_closes_on_request() {
    let mut composition = load(&["configs/navigation.pv3d.xml"]);
    let _running = serve("stage-worlds/navigation.world", &mut composition, 2.0);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);

    let egui_ctx = egui::Context::default();
    run_until(
        &mut viewer,
        "the blobfinder's window to list blobs",
        PATIENCE,
        |v| {
            texts_drawn(v, &egui_ctx)
                .iter()
                .any(|t| t.ends_with("in 80 × 60 px") && !t.starts_with("0 "))
        },
    );

    run_until(
        &mut viewer,
        "the gripper drawn open below r2",
        PATIENCE,
        |v| paddle_spread(v).is_some_and(|s| s > 0.25),
    );
    let gripper = viewer
        .titles()
        .iter()
        .position(|t| t.starts_with("Gripper"))
        .expect("a gripper plugin");
    assert!(viewer.use_service(gripper, "Close"));
    run_until(&mut viewer, "the paddles to close", PATIENCE, |v| {
        paddle_spread(v).is_some_and(|s| s < 0.1)
    });
}

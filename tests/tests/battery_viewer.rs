//! r0's power pack in stage-worlds/navigation.world through the viewer: the battery gauge
//! stands green over a full pack, and turns to the low warning once the pack is run down below
//! the composition's `lowPercent` (20), and r0's server row in the status panel says so.

use std::time::Duration;

use framework::scene::{Label, Rgba};
use pv3d::app::Viewer;
use tests::{load, run_until, serve, texts_drawn, viewer_for};

const PATIENCE: Duration = Duration::from_secs(20);
/// The power plugin's gauge colours: fine, and low (under `lowPercent`, not yet half of it).
const FINE: Rgba = Rgba::rgb(80, 200, 90);
const LOW: Rgba = Rgba::rgb(240, 170, 40);
/// What is left in the pack once run down: 15 % of r0's 20 kJ.
const RUN_DOWN_JOULES: f64 = 3000.0;

/// The label of r0's battery gauge, once drawn.
fn gauge_label(viewer: &Viewer) -> Option<Label> {
    viewer
        .scene()
        .iter()
        .find(|(_, o)| o.name.starts_with("battery"))
        .and_then(|(_, o)| o.geometry.labels.first().cloned())
}

#[test]
fn a_run_down_battery_turns_its_gauge_to_the_low_warning() {
    let mut composition = load(&["configs/navigation.pv3d.xml"]);
    let running = serve("stage-worlds/navigation.world", &mut composition, 1.0);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    assert!(
        viewer.titles().iter().any(|t| t.starts_with("Battery")),
        "{:?}",
        viewer.titles()
    );
    run_until(&mut viewer, "a full, green gauge", PATIENCE, |v| {
        gauge_label(v).is_some_and(|l| l.color == FINE && l.text == "100 %")
    });

    running.sim.lock().unwrap().robots[0]
        .battery
        .as_mut()
        .expect("r0 has a pack")
        .joules = RUN_DOWN_JOULES;
    run_until(&mut viewer, "the low warning", PATIENCE, |v| {
        gauge_label(v).is_some_and(|l| l.color == LOW && l.text == "15 %")
    });
    let egui_ctx = egui::Context::default();
    let texts = texts_drawn(&mut viewer, &egui_ctx);
    assert!(
        texts.iter().any(|t| t == "battery low: 15 % (under 20 %)"),
        "the status panel's note: {texts:?}"
    );
}

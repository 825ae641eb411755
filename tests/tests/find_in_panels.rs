//! Many robots stay usable: with the multirobot world's five robots (more components than
//! the find field waits for), typing a robot's name lists its entry and its server's status
//! row only, a summary counts the components by kind, and the selected robot comes first.

use std::time::Duration;

use tests::{load, run_until, serve, texts_drawn, viewer_for};

#[test]
fn typing_a_robots_name_lists_it_and_its_server_only() {
    let mut composition = load(&["configs/multirobot.pv3d.xml"]);
    let _running = serve("stage-worlds/multirobot.world", &mut composition, 1.0);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    run_until(&mut viewer, "five servers", Duration::from_secs(10), |v| {
        v.robots.as_ref().is_some_and(|r| r.clients().count() == 5)
    });
    let egui_ctx = egui::Context::default();
    // Two passes: egui lays some widgets out over two.
    texts_drawn(&mut viewer, &egui_ctx);
    let texts = texts_drawn(&mut viewer, &egui_ctx);
    assert!(
        texts.iter().any(|t| t.contains("components: 5 fiducial")),
        "a summary by kind: {texts:?}"
    );
    let robot_titles = |texts: &[String]| -> Vec<String> {
        texts
            .iter()
            .filter(|t| t.starts_with("Robot robot"))
            .cloned()
            .collect()
    };
    assert_eq!(robot_titles(&texts).len(), 5, "{texts:?}");

    viewer.find = "robot3".into();
    texts_drawn(&mut viewer, &egui_ctx);
    let found = texts_drawn(&mut viewer, &egui_ctx);
    let titles = robot_titles(&found);
    assert_eq!(titles.len(), 1, "{titles:?}");
    assert!(titles[0].starts_with("Robot robot3 "), "{titles:?}");
    assert!(
        found.iter().any(|t| t.ends_with("; 1 found")),
        "one server row: {found:?}"
    );
    let rows = found.iter().filter(|t| *t == "connected").count();
    assert_eq!(rows, 1, "only robot3's server is listed: {found:?}");

    viewer.find = "no such thing".into();
    let none = texts_drawn(&mut viewer, &egui_ctx);
    assert!(none.iter().any(|t| t == "no component matches"), "{none:?}");
}

//! The run-time component editor through the viewer's API, headless: components added from
//! the registry, parameters edited (the plugin re-created; a refused value leaves it as it
//! was), the visiting order changed, disabled (nothing drawn, saved `enabled="false"`, loaded
//! disabled) and enabled again, removed — and what is saved says so.

use std::path::PathBuf;
use std::sync::Arc;

use pv3d::app::{EditError, Viewer};
use pv3d::composition::{PluginInstance, parse_str};

fn instance(xml: &str) -> PluginInstance {
    PluginInstance {
        element: parse_str(xml, Arc::new(PathBuf::from("editor.xml"))).unwrap(),
        device: None,
    }
}

const ZONES: &str =
    r#"<plugin library="libpv3d_zones" id="zones"><zone name="dock">0 0  1 0  1 1</zone></plugin>"#;

fn viewer() -> Viewer {
    let instances = vec![
        instance(ZONES),
        instance(r#"<plugin library="libpv3d_lights" id="lights"/>"#),
    ];
    let viewer = Viewer::new(instances, plugins::standard_plugins(), &|_| None);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    viewer
}

fn has_dock(viewer: &Viewer) -> bool {
    viewer.scene().iter().any(|(_, o)| o.has_tag("zone:dock"))
}

fn saved_ids(viewer: &Viewer) -> Vec<String> {
    viewer.save().iter().map(|i| i.id().to_string()).collect()
}

#[test]
fn components_are_added_moved_and_removed_and_saved_so() {
    let mut viewer = viewer();
    assert!(viewer.component_libraries().contains(&"libpv3d_zones"));
    let at = viewer.add_component("libpv3d_zones", None).unwrap();
    assert_eq!(at, 2);
    assert_eq!(saved_ids(&viewer), vec!["zones", "lights", "zones-2"]);

    viewer.move_component(2, true).unwrap();
    assert_eq!(saved_ids(&viewer), vec!["zones", "zones-2", "lights"]);
    assert!(
        viewer.move_component(0, true).is_err(),
        "nothing before the first"
    );
    assert!(
        viewer.move_component(2, false).is_err(),
        "nothing after the last"
    );

    viewer.remove_component(0).unwrap();
    assert!(
        !has_dock(&viewer),
        "the removed zones took their drawing with them"
    );
    assert_eq!(saved_ids(&viewer), vec!["zones-2", "lights"]);
    assert_eq!(
        viewer.remove_component(7),
        Err(EditError::NoSuchComponent(7))
    );

    let e = viewer.add_component("libpv3d_nothing", None).unwrap_err();
    assert!(
        e.to_string().contains("known: ") && e.to_string().contains("libpv3d_zones"),
        "{e}"
    );
}

#[test]
fn a_disabled_component_draws_nothing_is_saved_disabled_and_comes_back() {
    let mut viewer = viewer();
    assert!(has_dock(&viewer));
    viewer.disable_component(0).unwrap();
    assert!(!has_dock(&viewer));
    assert_eq!(viewer.plugin_count(), 1);
    assert_eq!(viewer.disabled_titles(), vec!["libpv3d_zones zones"]);
    let saved = viewer.save();
    let zones = saved.iter().find(|i| i.id() == "zones").unwrap();
    assert_eq!(zones.element.attr("enabled"), Some("false"));

    // Loaded as saved, it stays disabled.
    let reloaded = Viewer::new(saved, plugins::standard_plugins(), &|_| None);
    assert!(!has_dock(&reloaded));
    assert_eq!(reloaded.disabled_titles().len(), 1);

    assert_eq!(viewer.enable_component(0).unwrap(), 0);
    assert!(has_dock(&viewer));
    assert!(viewer.disabled_titles().is_empty());
    assert_eq!(viewer.save()[0].element.attr("enabled"), None);
}

#[test]
fn a_parameter_edit_re_creates_the_plugin_and_a_bad_value_is_refused() {
    let mut viewer = viewer();
    viewer.set_component_param(0, "color", "#ff0000").unwrap();
    assert!(has_dock(&viewer));
    let saved = viewer.save();
    let color = saved[0].element.child("color").map(|e| e.text());
    assert_eq!(color.as_deref(), Some("#ff0000"));
    assert!(
        viewer
            .component_params(0)
            .contains(&("color".into(), "#ff0000".into())),
        "{:?}",
        viewer.component_params(0)
    );

    let e = viewer
        .set_component_param(0, "color", "blurple")
        .unwrap_err();
    assert!(e.to_string().contains("color"), "{e}");
    assert!(has_dock(&viewer), "made again as it was");
    assert_eq!(viewer.plugin_count(), 2);
    let saved = viewer.save();
    assert_eq!(
        saved[0].element.child("color").map(|e| e.text()).as_deref(),
        Some("#ff0000")
    );
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
}

#[test]
fn the_edited_composition_is_written_back_and_loads_as_edited() {
    use pv3d::app::ViewerBuilder;
    use pv3d::composition::{Composition, ParserRegistry, emit_document};

    let dir = tempfile::tempdir().unwrap();
    let original = dir.path().join("room.xml");
    std::fs::write(
        &original,
        format!(
            "<pv3d>\n  {ZONES}\n  <plugin library=\"libpv3d_lights\" id=\"lights\"/>\n</pv3d>\n"
        ),
    )
    .unwrap();
    let composition = Composition::load(&original, &ParserRegistry::standard()).unwrap();
    let mut viewer = ViewerBuilder::new(composition.clone()).build();
    viewer.set_component_param(0, "color", "#00ff00").unwrap();
    viewer.disable_component(0).unwrap();
    viewer.add_component("libpv3d_zones", None).unwrap();
    viewer.move_component(1, true).unwrap();

    let written = dir.path().join("edited.xml");
    std::fs::write(
        &written,
        emit_document(&composition, &viewer.save(), &written),
    )
    .unwrap();
    let text = std::fs::read_to_string(&written).unwrap();
    let reloaded = Composition::load(&written, &ParserRegistry::standard())
        .unwrap_or_else(|e| panic!("{e}\n{text}"));
    let again = ViewerBuilder::new(reloaded).build();
    assert!(again.errors.is_empty(), "{:?}", again.errors);
    assert_eq!(
        again.disabled_titles(),
        vec!["libpv3d_zones zones"],
        "{text}"
    );
    assert_eq!(again.plugin_count(), 2);
    assert!(!has_dock(&again), "the zones stayed disabled");
    assert!(text.contains("#00ff00"), "{text}");
}

#[test]
fn a_component_added_to_a_robot_takes_the_robots_device() {
    let robot = instance(
        r#"<plugin library="libpv3d_position2d" id="r0"><playerDeviceMask interface="position2d" index="0"/></plugin>"#,
    );
    let mut viewer = Viewer::new(vec![robot], plugins::standard_plugins(), &|_| None);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    let at = viewer.add_component("libpv3d_position2d", Some(0)).unwrap();
    let saved = viewer.save();
    let mask = saved[at]
        .element
        .child("playerDeviceMask")
        .expect("the robot's mask");
    assert_eq!(mask.attr("interface"), Some("position2d"));
    assert_eq!(
        viewer.add_component("libpv3d_zones", Some(9)),
        Err(EditError::NoSuchComponent(9))
    );
}

//! A plugin named outright with the address of its device (as an emitted composition names
//! every plugin) whose server answers only after the viewer started: it waits, is kept when
//! the session is saved, and is made for its device when the server answers.

use std::time::Duration;

use pv3d::composition::{Composition, ParserRegistry};
use tests::{run_until, serve_on_port, unused_port, viewer_for};

#[test]
fn a_named_plugin_waits_for_its_server_and_is_kept_meanwhile() {
    let port = unused_port();
    let dir = std::env::temp_dir().join(format!("pv3d-late-named-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("named.pv3d.xml");
    std::fs::write(
        &file,
        format!(
            r#"<pv3d>
  <handlers><playerClient host="127.0.0.1" port="{port}"/></handlers>
  <plugin library="libpv3d_laser" id="named">
    <playerDeviceMask host="127.0.0.1" port="{port}" interface="laser" index="0"/>
    <parentNode interface="position2d"/>
  </plugin>
  <plugin library="libpv3d_lights"/>
</pv3d>"#
        ),
    )
    .expect("composition written");
    let composition =
        Composition::load(&file, &ParserRegistry::standard()).expect("the composition loads");
    let mut viewer = viewer_for(&composition);
    assert_eq!(
        viewer.plugin_count(),
        1,
        "the lights only, while the server is down"
    );
    let saved_ids = |viewer: &pv3d::app::Viewer| -> Vec<String> {
        viewer.save().iter().map(|i| i.id().to_string()).collect()
    };
    assert!(
        saved_ids(&viewer).contains(&"named".to_string()),
        "a save keeps the waiting plugin"
    );

    let _running = serve_on_port("stage-worlds/simple.world", port);
    run_until(
        &mut viewer,
        "the named laser made for its device",
        Duration::from_secs(15),
        |v| v.plugin_count() == 2,
    );
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    let saved = viewer.save();
    let named: Vec<_> = saved.iter().filter(|i| i.id() == "named").collect();
    assert_eq!(named.len(), 1, "made once, no longer waiting");
    let mask = named[0]
        .element
        .child("playerDeviceMask")
        .expect("its mask");
    assert_eq!(
        mask.attr("driver"),
        Some("rangertolaser"),
        "bound to the server's laser"
    );
    let parent = named[0].element.child("parentNode").expect("its parent");
    assert_eq!(parent.attr("index"), Some("0"));
    let _ = std::fs::remove_dir_all(&dir);
}

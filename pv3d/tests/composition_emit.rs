//! Compositions written back: the emitted file loads to the same instances, extension
//! elements are written as they were, sensors of robots sharing a port keep their robot,
//! plugins named outright are bound to their device, relative files are rewritten.

mod support;

use std::fs;
use std::path::{Path, PathBuf};

use pv3d::composition::{Composition, ParserRegistry, PluginInstance, emit_document, instantiate};
use support::compositions::{device, load, paper_example, write};

fn summary(list: &[PluginInstance]) -> Vec<(String, String, Option<String>)> {
    list.iter()
        .map(|i| {
            (
                i.library().to_string(),
                i.id().to_string(),
                i.element
                    .child("playerDeviceMask")
                    .and_then(|m| m.attr("index"))
                    .map(str::to_string),
            )
        })
        .collect()
}

#[test]
fn emitted_config_loads_back_to_the_same_instances() {
    let dir = tempfile::tempdir().unwrap();
    let composition = load(&[paper_example(dir.path())]).unwrap();
    let devices = [
        device(6665, "laser:0", "sicklms200"),
        device(6665, "laser:2", "stage"),
    ];
    let instances = instantiate(&composition, &devices);

    let target = dir.path().join("emitted.xml");
    let emitted = write(
        dir.path(),
        "emitted.xml",
        &emit_document(&composition, &instances, &target),
    );
    let reloaded = load(std::slice::from_ref(&emitted)).unwrap();
    assert!(
        reloaded.handlers.is_empty(),
        "handlers were applied, not copied"
    );
    let again = instantiate(&reloaded, &devices);
    assert_eq!(summary(&again), summary(&instances));
    // And emitting again is stable.
    let twice = emit_document(&reloaded, &again, &target);
    assert_eq!(twice, fs::read_to_string(&emitted).unwrap());
}

#[test]
fn zones_become_one_plugin_and_are_written_back_as_they_were() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(
        dir.path(),
        "zones.xml",
        r##"<pv3d>
  <addParser element="zone"/>
  <zone name="dock" color="#40c0ff">0 0  2 0  2 2</zone>
  <plugin library="libpv3d_ground"/>
  <zone name="keep out">5 5  6 5  6 6  5 6</zone>
</pv3d>"##,
    );
    let parsers = ParserRegistry::standard();
    let composition = Composition::load(&file, &parsers).unwrap();
    let instances = instantiate(&composition, &[]);
    let zones: Vec<&PluginInstance> = instances
        .iter()
        .filter(|i| i.library() == "libpv3d_zones")
        .collect();
    assert_eq!(zones.len(), 1, "every <zone> goes to one plugin");
    let names: Vec<&str> = zones[0]
        .element
        .elements()
        .filter_map(|e| e.attr("name"))
        .collect();
    assert_eq!(names, ["dock", "keep out"]);

    let emitted = emit_document(&composition, &instances, &dir.path().join("again.xml"));
    assert_eq!(emitted.matches("<addParser").count(), 1, "{emitted}");
    assert_eq!(emitted.matches("<zone ").count(), 2, "{emitted}");
    assert!(!emitted.contains("libpv3d_zones"), "{emitted}");
    let again = write(dir.path(), "again.xml", &emitted);
    let reloaded = Composition::load(&again, &parsers).unwrap();
    assert_eq!(
        summary(&instantiate(&reloaded, &[])),
        summary(&instances),
        "the same plugins after a round trip"
    );
}

fn repo_file(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(path)
}

fn parent_index(instance: &PluginInstance) -> Option<&str> {
    instance
        .element
        .child("parentNode")
        .and_then(|p| p.attr("index"))
}

#[test]
fn sensors_of_robots_sharing_a_port_hang_below_their_own_robot() {
    // Two robots on one port, numbered as Stage numbers them (the captures' r0 and r2).
    let composition = load(&[repo_file("configs/stage-world.pv3d.xml")]).unwrap();
    let devices = [
        device(6665, "position2d:0", "stage"),
        device(6665, "laser:0", "rangertolaser"),
        device(6665, "fiducial:0", "stage"),
        device(6665, "position2d:1", "stage"),
        device(6665, "laser:1", "rangertolaser"),
        device(6665, "fiducial:1", "stage"),
    ];
    let instances = instantiate(&composition, &devices);
    let parents: Vec<(String, Option<&str>)> = instances
        .iter()
        .filter(|i| i.element.child("parentNode").is_some())
        .map(|i| {
            let d = i.device.as_ref().unwrap();
            (d.addr.to_string(), parent_index(i))
        })
        .collect();
    assert_eq!(
        parents,
        [
            ("laser:0".to_string(), Some("0")),
            ("laser:1".to_string(), Some("1")),
            ("fiducial:0".to_string(), Some("0")),
            ("fiducial:1".to_string(), Some("1")),
        ]
    );
    // The emitted composition says so outright.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.xml");
    let text = emit_document(&composition, &instances, &out);
    assert_eq!(
        text.matches(r#"<parentNode interface="position2d" index="1"/>"#)
            .count(),
        2,
        "{text}"
    );
}

#[test]
fn a_plugin_named_outright_is_bound_to_the_device_its_mask_names() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "named.xml",
        r#"<pv3d>
  <plugin library="libpv3d_laser" id="second">
    <playerDeviceMask host="localhost" port="6666" interface="laser" index="1"/>
    <parentNode interface="position2d" index="*"/>
  </plugin>
  <plugin library="libpv3d_sonar" id="absent">
    <playerDeviceMask interface="sonar" index="0"/>
  </plugin>
  <plugin library="libpv3d_lights"/>
</pv3d>"#,
    );
    let composition = load(&[path]).unwrap();
    let devices = [
        device(6665, "laser:1", "stage"),
        device(6666, "laser:0", "stage"),
        device(6666, "laser:1", "sicklms200"),
    ];
    let instances = instantiate(&composition, &devices);
    let second = instances[0].device.as_ref().expect("bound");
    assert_eq!(
        (second.port, second.addr.to_string()),
        (6666, "laser:1".into())
    );
    assert_eq!(
        instances[0]
            .element
            .child("playerDeviceMask")
            .unwrap()
            .attr("driver"),
        Some("sicklms200"),
        "the mask is now the device's full address"
    );
    assert_eq!(parent_index(&instances[0]), Some("1"));
    assert!(instances[1].waits_for_device(), "no sonar was reported");
    assert!(!instances[2].waits_for_device(), "lights need no device");
}

#[test]
fn relative_files_are_rewritten_for_where_the_composition_is_written() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "in/bitmaps/room.png", "not read here");
    let path = write(
        dir.path(),
        "in/room.xml",
        r#"<pv3d>
  <plugin library="libpv3d_ground"><bitmap>bitmaps/room.png</bitmap><bitmapSize>10 8</bitmapSize></plugin>
</pv3d>"#,
    );
    let composition = load(&[path]).unwrap();
    let instances = instantiate(&composition, &[]);
    let out = dir.path().join("elsewhere/deeper/room.xml");
    fs::create_dir_all(out.parent().unwrap()).unwrap();
    let text = emit_document(&composition, &instances, &out);
    assert!(
        text.contains("<bitmap>../../in/bitmaps/room.png</bitmap>"),
        "{text}"
    );
    assert!(text.contains("<bitmapSize>10 8</bitmapSize>"), "{text}");
    // Written beside the input, nothing changes.
    let beside = emit_document(&composition, &instances, &dir.path().join("in/copy.xml"));
    assert!(
        beside.contains("<bitmap>bitmaps/room.png</bitmap>"),
        "{beside}"
    );
}

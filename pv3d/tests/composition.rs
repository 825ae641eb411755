//! Compositions from files: includes, masks, instantiation, errors with positions, emit round trip.

use std::fs;
use std::path::{Path, PathBuf};

use pv3d::composition::{
    Composition, ConfigError, FoundDevice, ParserRegistry, PluginInstance, emit_document,
    instantiate,
};

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    if let Some(parent) = path.parent() {
        fs::create_dir_all(parent).unwrap();
    }
    fs::write(&path, text).unwrap();
    path
}

fn device(port: u16, addr: &str, driver: &str) -> FoundDevice {
    FoundDevice {
        host: "localhost".into(),
        port,
        addr: addr.parse().unwrap(),
        driver: driver.into(),
    }
}

/// The paper's Fig. 4 composition, with the Fig. 5 template in a subfolder.
fn paper_example(dir: &Path) -> PathBuf {
    write(
        dir,
        "templates/laser.pv3d.xml",
        r#"<plugin library="libpv3d_laser" id="laser">
  <playerDeviceMask host="localhost" port="6665" interface="laser" index="0"/>
  <parentNode interface="position2d" index="0"/>
  <fillLaserCspace>1</fillLaserCspace>
  <drawLaserCspace>1</drawLaserCspace>
</plugin>"#,
    );
    write(
        dir,
        "paper.xml",
        r#"<pv3d xmlns:pv3d="http://miarn.sf.net" xmlns:xi="http://www.w3.org/2001/XInclude">
  <handlers>
    <playerClient host="localhost" port="6665"/>
    <playerDeviceMask interface="laser">
      <xi:include href="templates/laser.pv3d.xml"/>
    </playerDeviceMask>
  </handlers>
  <plugin library="libpv3d_lights"/>
  <plugin library="libpv3d_ground"/>
</pv3d>"#,
    )
}

fn load(paths: &[PathBuf]) -> Result<Composition, ConfigError> {
    Composition::load_files(paths, &ParserRegistry::default())
}

#[test]
fn the_papers_composition_instantiates_one_laser_per_device() {
    let dir = tempfile::tempdir().unwrap();
    let composition = load(&[paper_example(dir.path())]).unwrap();
    assert_eq!(composition.clients.len(), 1);
    assert_eq!(composition.handlers.len(), 1);

    let devices = [
        device(6665, "position2d:0", "stage"),
        device(6665, "laser:0", "sicklms200"),
        device(6665, "laser:1", "sicklms200"),
        device(6665, "sonar:0", "stage"),
    ];
    let instances = instantiate(&composition, &devices);
    let libraries: Vec<&str> = instances.iter().map(|i| i.library()).collect();
    assert_eq!(
        libraries,
        [
            "libpv3d_laser",
            "libpv3d_laser",
            "libpv3d_lights",
            "libpv3d_ground"
        ]
    );

    // The template's mask now names the found device.
    let mask = instances[1].element.child("playerDeviceMask").unwrap();
    assert_eq!(mask.attr("interface"), Some("laser"));
    assert_eq!(mask.attr("index"), Some("1"));
    assert_eq!(mask.attr("driver"), Some("sicklms200"));
    // The template's other parameters are kept.
    assert_eq!(
        instances[1]
            .element
            .child("fillLaserCspace")
            .unwrap()
            .text(),
        "1"
    );
    // Two lasers from one template get distinct ids.
    assert_ne!(instances[0].id(), instances[1].id());
}

#[test]
fn masks_filter_by_driver_index_and_server() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "masks.xml",
        r#"<pv3d>
  <handlers>
    <playerDeviceMask mask="laser:sicklms200:*"><plugin library="libpv3d_laser" id="sick"/></playerDeviceMask>
    <playerDeviceMask interface="ranger" driver="stage" index="1" port="6666"><plugin library="libpv3d_ranger" id="r"/></playerDeviceMask>
    <playerDeviceMask interface="camera"><plugin library="libpv3d_camera" id="cam"/></playerDeviceMask>
  </handlers>
</pv3d>"#,
    );
    let composition = load(&[path]).unwrap();
    let devices = [
        device(6665, "laser:0", "sicklms200"),
        device(6665, "laser:1", "stage"),
        device(6665, "ranger:1", "stage"),
        device(6666, "ranger:1", "stage"),
        device(6666, "ranger:0", "stage"),
    ];
    let instances = instantiate(&composition, &devices);
    let made: Vec<(String, u16)> = instances
        .iter()
        .map(|i| (i.library().to_string(), i.device.as_ref().unwrap().port))
        .collect();
    assert_eq!(
        made,
        [
            ("libpv3d_laser".to_string(), 6665),
            ("libpv3d_ranger".to_string(), 6666)
        ]
    );
}

#[test]
fn several_files_merge() {
    let dir = tempfile::tempdir().unwrap();
    let a = paper_example(dir.path());
    let b = write(
        dir.path(),
        "sonar.xml",
        r#"<plugin library="libpv3d_sonar" id="s"/>"#,
    );
    let composition = load(&[a, b]).unwrap();
    assert_eq!(composition.plugins.len(), 3);
    assert_eq!(composition.sources.len(), 2);
}

fn error_text(result: Result<Composition, ConfigError>) -> String {
    result.unwrap_err().to_string()
}

#[test]
fn include_loops_are_refused_with_the_chain() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "b.xml",
        r#"<plugin library="x"><xi:include href="a.xml"/></plugin>"#,
    );
    let a = write(
        dir.path(),
        "a.xml",
        "<pv3d>\n  <plugin library=\"y\"><xi:include href=\"b.xml\"/></plugin>\n</pv3d>",
    );
    let text = error_text(load(&[a]));
    assert!(
        text.contains("include loop: a.xml -> b.xml -> a.xml"),
        "{text}"
    );
    assert!(
        text.contains("b.xml:1:"),
        "the error points into b.xml: {text}"
    );
}

#[test]
fn a_missing_include_names_the_href() {
    let dir = tempfile::tempdir().unwrap();
    let a = write(
        dir.path(),
        "a.xml",
        "<pv3d>\n  <handlers>\n    <playerDeviceMask interface=\"laser\">\n      <xi:include href=\"nope.xml\"/>\n",
    );
    // An unclosed document first: a parse error with a position.
    assert!(error_text(load(std::slice::from_ref(&a))).contains("a.xml:"));
    fs::write(
        &a,
        "<pv3d>\n  <handlers>\n    <playerDeviceMask interface=\"laser\">\n      <xi:include href=\"nope.xml\"/>\n    </playerDeviceMask>\n  </handlers>\n</pv3d>",
    )
    .unwrap();
    let text = error_text(load(&[a]));
    assert!(
        text.contains("a.xml:4:19: included file \"nope.xml\" not found"),
        "{text}"
    );
}

#[test]
fn unknown_elements_attributes_and_values_say_what_was_expected() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            "<pv3d>\n  <plugn library=\"x\"/>\n</pv3d>",
            "2:3: unknown element <plugn> in <pv3d>; expected <handlers>, <plugin> or <addParser>",
        ),
        (
            "<pv3d>\n  <plugin librari=\"x\"/>\n</pv3d>",
            "2:11: unknown attribute librari on <plugin>; expected library, id",
        ),
        (
            "<pv3d>\n  <plugin id=\"x\"/>\n</pv3d>",
            "2:3: <plugin> needs a library attribute",
        ),
        (
            "<pv3d><handlers>\n<playerClient port=\"http\"/></handlers></pv3d>",
            "2:15: port \"http\" is not a number",
        ),
        (
            "<pv3d><handlers>\n<playerDeviceMask interface=\"lazer\"/></handlers></pv3d>",
            "2:1: bad device mask: unknown interface \"lazer\"",
        ),
        (
            "<pv3d>\n<addParser element=\"warp\"/></pv3d>",
            "2:12: no parser for <warp> is built into pv3d",
        ),
        ("<config/>", "1:1: unknown root element <config>"),
    ];
    for (i, (xml, expected)) in cases.iter().enumerate() {
        let path = write(dir.path(), &format!("bad{i}.xml"), xml);
        let text = error_text(load(&[path]));
        assert!(
            text.contains(&format!("bad{i}.xml:{expected}")),
            "case {i}: {text}"
        );
    }
}

#[test]
fn extension_elements_need_their_parser_enabled() {
    let dir = tempfile::tempdir().unwrap();
    let parsers = ParserRegistry::new(&["zone"]);
    let without = write(
        dir.path(),
        "z1.xml",
        "<pv3d>\n  <zone name=\"a\"/>\n</pv3d>",
    );
    let text = Composition::load(&without, &parsers)
        .unwrap_err()
        .to_string();
    assert!(
        text.contains("enable it with <addParser element=\"zone\"/>"),
        "{text}"
    );
    let with = write(
        dir.path(),
        "z2.xml",
        "<pv3d>\n  <zone name=\"a\"/>\n  <addParser element=\"zone\"/>\n</pv3d>",
    );
    let composition = Composition::load(&with, &parsers).unwrap();
    assert_eq!(composition.extensions.len(), 1);
}

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

//! Compositions from files: includes, masks, instantiation, errors with positions. (Writing
//! them back: `composition_emit.rs`.)

mod support;

use std::fs;

use pv3d::composition::{Composition, ConfigError, ParserRegistry, instantiate};
use support::compositions::{device, load, paper_example, write};

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

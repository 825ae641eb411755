//! A composition the Relax NG schema accepts but that means nothing: every standard plugin,
//! given parameters the shipped compositions use (their names gathered from configs/) with
//! values that are wrong in every way — negative, huge, NaN, empty, not numbers, odd colours.
//! Each plugin is made and run as the viewer would: made, or refused with the parameter named —
//! never a panic.
#![no_main]

use std::sync::OnceLock;

use framework::config::{DeviceRef, Param, PluginConfig};
use framework::testing::Harness;
use libfuzzer_sys::arbitrary::{Arbitrary, Unstructured};
use libfuzzer_sys::fuzz_target;

/// Values a parameter might be given by mistake.
const VALUES: &[&str] = &[
    "", "0", "-1", "1", "3", "0.5", "-0.0", "1e308", "-1e308", "NaN", "inf", "-inf", "1e-320",
    "abc", "#zzzzzz", "#ff0000", "#ff000080", "1 2", "1 2 3", "1 2 3 4 5 6 7", "true", "false",
    "laser:0", "position2d:*", "localhost:6665", "../../nope.png", "$x^2$", "  7  ", "1,2",
];

/// Interfaces a plugin's device may be.
const DEVICES: &[&str] = &[
    "position2d:0", "laser:0", "ranger:1", "sonar:0", "fiducial:0", "camera:0", "map:0",
    "localize:0", "planner:0", "power:0", "bumper:0", "ir:0", "gripper:0", "blobfinder:0",
    "ptz:0", "pointcloud3d:0", "speech:0",
];

/// Every element name used inside a `<plugin>` of the shipped compositions and templates.
fn parameter_names() -> &'static [String] {
    static NAMES: OnceLock<Vec<String>> = OnceLock::new();
    NAMES.get_or_init(|| {
        let configs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs");
        let mut names = Vec::new();
        for dir in [configs.clone(), configs.join("templates")] {
            let Ok(entries) = std::fs::read_dir(&dir) else { continue };
            for entry in entries.flatten() {
                let text = std::fs::read_to_string(entry.path()).unwrap_or_default();
                // Opening tags: `<name` followed by space, `>` or `/`.
                for part in text.split('<').skip(1) {
                    let name: String = part
                        .chars()
                        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                        .collect();
                    if !name.is_empty() && !names.contains(&name) {
                        names.push(name);
                    }
                }
            }
        }
        names.sort();
        names
    })
}

fn pick<'a>(u: &mut Unstructured<'_>, from: &'a [&'a str]) -> &'a str {
    from[u.choose_index(from.len()).unwrap_or(0)]
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let registry = plugins::standard_plugins();
    let libraries: Vec<&'static str> = registry.libraries().collect();
    let library = libraries[u.choose_index(libraries.len()).unwrap_or(0)];
    let names = parameter_names();
    let mut params = Vec::new();
    for _ in 0..u.int_in_range(0..=8u8).unwrap_or(0) {
        let name = &names[u.choose_index(names.len()).unwrap_or(0)];
        let text = if bool::arbitrary(&mut u).unwrap_or(false) {
            pick(&mut u, VALUES).to_string()
        } else {
            String::arbitrary(&mut u).unwrap_or_default()
        };
        let mut param = Param::new(name, &text);
        if bool::arbitrary(&mut u).unwrap_or(false) {
            param.attributes = vec![(
                pick(&mut u, &["interface", "index", "height", "color", "name", "x", "y"]).into(),
                pick(&mut u, VALUES).into(),
            )];
        }
        param.origin = "fuzz.xml:2:3".into();
        params.push(param);
    }
    let device = bool::arbitrary(&mut u).unwrap_or(true).then(|| DeviceRef {
        host: "localhost".into(),
        port: 6665,
        addr: pick(&mut u, DEVICES).parse().unwrap(),
        driver: "stage".into(),
    });
    let config = PluginConfig {
        library: library.into(),
        id: "fuzzed".into(),
        device,
        params,
        origin: "fuzz.xml:1:1".into(),
        ..PluginConfig::default()
    };
    let mut harness = Harness::with_registry(registry);
    match harness.make(config) {
        Ok(mut plugin) => {
            plugin.initialize(&mut harness.ctx());
            for _ in 0..3 {
                harness.run_changes_scene(plugin.as_mut());
            }
            let _ = plugin.save();
            plugin.clean(&mut harness.ctx());
        }
        Err(e) => assert!(e.to_string().contains("fuzz.xml"), "{e}"),
    }
});

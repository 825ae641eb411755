//! Every file in configs/ validates against configs/pv3d.rng with a real Relax NG validator
//! (xmllint, from Debian's libxml2-utils, installed by scripts/setup.sh), and loads with our
//! own parser.

use std::path::{Path, PathBuf};
use std::process::Command;

use pv3d::composition::{Composition, ParserRegistry};

fn configs_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs")
}

fn xml_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            xml_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "xml") {
            out.push(path);
        }
    }
}

/// Command grammars (`*.grammar.xml`) have a schema of their own.
fn is_grammar(file: &Path) -> bool {
    file.to_string_lossy().ends_with(".grammar.xml")
}

fn xmllint(file: &Path) -> std::process::Output {
    let schema = configs_dir().join(if is_grammar(file) {
        "commands.grammar.rng"
    } else {
        "pv3d.rng"
    });
    Command::new("xmllint")
        .arg("--noout")
        .arg("--relaxng")
        .arg(&schema)
        .arg(file)
        .output()
        .expect("xmllint not found: run `bash scripts/setup.sh` (installs libxml2-utils)")
}

#[test]
fn every_config_validates_against_the_schema_and_loads() {
    let mut files = Vec::new();
    xml_files(&configs_dir(), &mut files);
    assert!(
        files.len() >= 3,
        "configs/ should hold example compositions"
    );
    for file in &files {
        let out = xmllint(file);
        assert!(
            out.status.success(),
            "{} does not validate:\n{}",
            file.display(),
            String::from_utf8_lossy(&out.stderr)
        );
        if is_grammar(file) {
            pv3d::commands::Grammar::load(file)
                .unwrap_or_else(|e| panic!("{} does not load: {e}", file.display()));
            continue;
        }
        Composition::load(file, &ParserRegistry::standard())
            .unwrap_or_else(|e| panic!("{} does not load: {e}", file.display()));
    }
}

#[test]
fn the_schema_refuses_what_the_loader_refuses() {
    let dir = tempfile::tempdir().unwrap();
    for (i, bad) in [
        "<pv3d><plugn library=\"libpv3d_laser\"/></pv3d>",
        "<pv3d><plugin id=\"no-library\"/></pv3d>",
        "<pv3d><handlers><playerClient port=\"http\"/></handlers></pv3d>",
        "<pv3d><handlers><playerDeviceMask index=\"x\"/></handlers></pv3d>",
        "<pv3d><plugin library=\"libpv3d_laser\"><parentNode index=\"x\"/></plugin></pv3d>",
    ]
    .iter()
    .enumerate()
    {
        let path = dir.path().join(format!("bad{i}.xml"));
        std::fs::write(&path, bad).unwrap();
        assert!(!xmllint(&path).status.success(), "schema accepted {bad}");
        assert!(
            Composition::load(&path, &ParserRegistry::standard()).is_err(),
            "loader accepted {bad}"
        );
    }
}

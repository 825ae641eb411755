//! A spec with a mistake is refused before any program runs, with the file, line and field.

use std::path::{Path, PathBuf};
use std::process::Command;

use player_grade::spec::Spec;

fn worlds() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds")
}

const GOOD: &str = "world = \"WORLD\"\nrobot = \"r0\"\ntime_limit = 60\nseed = 1\n\n[[check]]\nname = \"reaches the charger\"\nkind = \"reach\"\nx = 3.0\ny = 2.0\nradius = 0.5\npoints = 60\n";

/// The error of `text` as a spec in a folder of its own.
fn error_of(text: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("spec.toml");
    let text = text.replace(
        "WORLD",
        &worlds().join("simple.world").display().to_string(),
    );
    std::fs::write(&path, &text).unwrap();
    let error = Spec::load(&path).unwrap_err().to_string();
    error.replace(&path.display().to_string(), "spec.toml")
}

#[test]
fn a_good_spec_reads() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("spec.toml");
    std::fs::write(
        &path,
        GOOD.replace(
            "WORLD",
            &worlds().join("simple.world").display().to_string(),
        ),
    )
    .unwrap();
    let spec = Spec::load(&path).unwrap();
    assert_eq!(
        (spec.robot.as_str(), spec.time_limit, spec.checks.len()),
        ("r0", 60.0, 1)
    );
    assert_eq!(spec.max_score(), 60.0);
    assert!(spec.lockstep, "lockstep unless told otherwise");
}

#[test]
fn each_mistake_is_named_where_it_is() {
    assert_eq!(
        error_of(&GOOD.replace("kind = \"reach\"", "kind = \"teleport\"")),
        "spec.toml:8:8: check \"reaches the charger\", kind: unknown check kind \"teleport\"; \
         known: reach, no_stall, end_in_zone, avoid_zone, distance, stop_at_end, follow, python"
    );
    assert_eq!(
        error_of(&GOOD.replace("time_limit = 60", "time_limit = -5")),
        "spec.toml:3:14: time_limit: must be more than 0, got -5"
    );
    let missing = error_of(&GOOD.replace("WORLD", "nowhere.world"));
    assert!(
        missing.starts_with("spec.toml:1:9: world: no world file at "),
        "{missing}"
    );
    assert_eq!(
        error_of(&GOOD.replace("robot = \"r0\"", "robot = \"r7\"")),
        format!(
            "spec.toml:2:9: robot: {} has no robot \"r7\" (it has [\"r0\"])",
            worlds().join("simple.world").display()
        )
    );
    assert_eq!(
        error_of(&GOOD.replace("radius = 0.5", "radius = 0")),
        "spec.toml:11:10: check \"reaches the charger\", radius: must be more than 0, got 0"
    );
    assert_eq!(
        error_of(&GOOD.replace("points = 60", "points = -1")),
        "spec.toml:12:10: check \"reaches the charger\", points: must be at least 0, got -1"
    );
    let unknown = error_of(&GOOD.replace("seed = 1", "sed = 1"));
    assert!(
        unknown.starts_with("spec.toml:4:1: spec: unknown field `sed`"),
        "{unknown}"
    );
    let broken = error_of(&GOOD.replace("y = 2.0", "y = = 2.0"));
    assert!(broken.starts_with("spec.toml:10:5: spec: "), "{broken}");
    let follow = error_of(&GOOD.replace("kind = \"reach\"", "kind = \"follow\"\ntarget = \"r9\""));
    assert!(
        follow.starts_with(
            "spec.toml:9:10: check \"reaches the charger\", target: the world has no robot \"r9\""
        ),
        "{follow}"
    );
    let python = error_of(&GOOD.replace(
        "kind = \"reach\"",
        "kind = \"python\"\nfile = \"gone.py\"\nfunction = \"f\"",
    ));
    assert!(python.contains("file: no Python file at"), "{python}");
}

#[test]
fn the_program_refuses_a_bad_spec_before_running_anything() {
    let dir = tempfile::tempdir().unwrap();
    let spec = dir.path().join("spec.toml");
    std::fs::write(&spec, GOOD.replace("WORLD", "missing.world")).unwrap();
    let program = dir.path().join("student.py");
    std::fs::write(&program, "open('ran', 'w')\n").unwrap();
    let out = dir.path().join("grades");
    let done = Command::new(env!("CARGO_BIN_EXE_player-grade"))
        .arg(&spec)
        .arg(&program)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(!done.status.success());
    let stderr = String::from_utf8_lossy(&done.stderr);
    assert!(
        stderr.contains("spec.toml:1:9: world: no world file at"),
        "{stderr}"
    );
    assert!(
        !out.exists() && !dir.path().join("ran").exists(),
        "nothing ran"
    );
}

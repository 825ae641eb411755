//! The example class graded as a teacher would: `player-grade` on the programs written for it
//! — careful, reckless, crashing, spinning, never commanding, forking, printing without end —
//! gives each its expected score, twice and identically (recordings byte for byte), once with
//! both cores busy and once one program at a time; and its files are what Gradescope, JUnit
//! readers and a browser expect.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The Python with player3 that scripts/setup.sh made.
fn python() -> PathBuf {
    let python = repo().join(".venv/bin/python");
    assert!(
        python.exists(),
        "no {}: run scripts/setup.sh first",
        python.display()
    );
    python
}

fn grade_example(out: &Path, jobs: &str) -> BTreeMap<String, f64> {
    let example = repo().join("player-grade/example");
    let mut submissions: Vec<PathBuf> = std::fs::read_dir(example.join("submissions"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    submissions.sort();
    let done = Command::new(env!("CARGO_BIN_EXE_player-grade"))
        .arg(example.join("spec.toml"))
        .args(&submissions)
        .arg("--python")
        .arg(python())
        .arg("--out")
        .arg(out)
        .args(["--jobs", jobs])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&done.stderr);
    assert!(done.status.success(), "{stderr}");
    let mut scores = BTreeMap::new();
    for line in std::fs::read_to_string(out.join("summary.csv"))
        .unwrap()
        .lines()
        .skip(1)
    {
        let fields: Vec<&str> = line.split(',').collect();
        scores.insert(fields[0].to_string(), fields[1].parse().unwrap());
    }
    scores
}

#[test]
fn the_example_class_gets_its_scores_twice_and_identically() {
    let dir = tempfile::tempdir().unwrap();
    let (busy, alone) = (dir.path().join("busy"), dir.path().join("alone"));
    let scores = grade_example(&busy, "2");
    let expected: BTreeMap<String, f64> = [
        ("careful", 100.0),
        ("chatty", 40.0),
        ("crashing", 30.0),
        ("forking", 20.0),
        ("idle", 40.0),
        ("reckless", 15.0),
        ("spinning", 40.0),
    ]
    .into_iter()
    .map(|(n, s)| (n.to_string(), s))
    .collect();
    assert_eq!(scores, expected);
    assert_eq!(grade_example(&alone, "1"), expected);
    let summary = |d: &Path| std::fs::read_to_string(d.join("summary.csv")).unwrap();
    assert_eq!(
        summary(&busy),
        summary(&alone),
        "the same verdicts, word for word"
    );
    for name in expected.keys() {
        let recording = |d: &Path| std::fs::read(d.join(name).join("run.mcap")).unwrap();
        let (a, b) = (recording(&busy), recording(&alone));
        assert!(a.len() > 1000, "{name}: a recording");
        assert!(a == b, "{name}: the same recording, byte for byte");
        let picture = image::open(busy.join(name).join("path.png")).unwrap();
        assert!(picture.width() >= 100 && picture.height() >= 100, "{name}");
    }
    // No program outlives its run: the forking one's children were killed with it.
    let left = Command::new("pgrep")
        .args(["-f", "forking.py"])
        .output()
        .unwrap();
    assert!(
        left.stdout.is_empty(),
        "left running: {}",
        String::from_utf8_lossy(&left.stdout)
    );
}

/// Gradescope's results.json: what its documentation names, with the types it gives.
fn check_gradescope(results: &Value) {
    assert!(results["score"].is_number());
    assert!(results["execution_time"].is_number());
    assert!(results["output"].is_string());
    let visible = ["hidden", "after_due_date", "after_published", "visible"];
    assert!(visible.contains(&results["visibility"].as_str().unwrap()));
    assert!(visible.contains(&results["stdout_visibility"].as_str().unwrap()));
    let tests = results["tests"].as_array().unwrap();
    assert_eq!(tests.len(), 5);
    let total: f64 = tests.iter().map(|t| t["score"].as_f64().unwrap()).sum();
    assert_eq!(total, results["score"].as_f64().unwrap());
    for test in tests {
        assert!(test["name"].is_string() && test["output"].is_string());
        assert!(test["score"].as_f64().unwrap() <= test["max_score"].as_f64().unwrap());
        assert!(["passed", "failed"].contains(&test["status"].as_str().unwrap()));
        assert!(test["number"].is_string());
    }
}

#[test]
fn each_submission_says_what_happened_in_files_other_tools_read() {
    let dir = tempfile::tempdir().unwrap();
    let example = repo().join("player-grade/example");
    let submissions =
        ["crashing.py", "chatty.py", "careful.py"].map(|n| example.join("submissions").join(n));
    let done = Command::new(env!("CARGO_BIN_EXE_player-grade"))
        .arg(example.join("spec.toml"))
        .args(submissions)
        .arg("--python")
        .arg(python())
        .arg("--out")
        .arg(dir.path())
        .output()
        .unwrap();
    assert!(
        done.status.success(),
        "{}",
        String::from_utf8_lossy(&done.stderr)
    );
    let results = |name: &str| -> Value {
        let text = std::fs::read_to_string(dir.path().join(name).join("results.json")).unwrap();
        serde_json::from_str(&text).unwrap()
    };
    let crashing = results("crashing");
    check_gradescope(&crashing);
    let output = crashing["output"].as_str().unwrap();
    assert!(output.contains("exit status 1"), "{output}");
    assert!(
        output.contains("Error: ZeroDivisionError: division by zero"),
        "{output}"
    );
    assert!(
        output.contains("about to divide"),
        "the program's own lines: {output}"
    );
    let chatty = results("chatty");
    check_gradescope(&chatty);
    let output = chatty["output"].as_str().unwrap();
    assert!(output.contains("never commanded the robot"), "{output}");
    assert!(
        output.contains("bytes printed; the last"),
        "cut, not whole: {output}"
    );
    assert!(output.len() < 64 * 1024, "{} bytes", output.len());
    let careful = results("careful");
    check_gradescope(&careful);
    assert_eq!(careful["score"].as_f64(), Some(100.0));
    let junit = std::fs::read_to_string(dir.path().join("junit.xml")).unwrap();
    assert!(junit.starts_with("<?xml"));
    assert!(junit.contains("tests=\"15\""), "{junit}");
    assert!(junit.contains("<testcase classname=\"careful\" name=\"reaches the charger\"/>"));
    let html = std::fs::read_to_string(dir.path().join("report.html")).unwrap();
    assert_eq!(html.matches("<tr><td class=\"name\">").count(), 3);
    assert!(html.contains("<img src=\"careful/path.png\""));
    // The page as a browser shows it: a row per student, every picture loaded, no error.
    let shot = dir.path().join("report.png");
    let seen = Command::new("node")
        .arg(repo().join("tests/web/report.mjs"))
        .arg(dir.path().join("report.html"))
        .arg(&shot)
        .current_dir(repo().join("tests/web"))
        .output()
        .unwrap();
    assert!(
        seen.status.success(),
        "{}",
        String::from_utf8_lossy(&seen.stderr)
    );
    let seen: Value = serde_json::from_slice(&seen.stdout).unwrap();
    assert_eq!(seen["errors"], serde_json::json!([]), "{seen}");
    let rows = seen["rows"].as_array().unwrap();
    let names: Vec<&str> = rows.iter().map(|r| r["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["crashing", "chatty", "careful"]);
    assert_eq!(rows[2]["score"], "100 / 100");
    assert_eq!(
        (rows[2]["passed"].as_u64(), rows[2]["failed"].as_u64()),
        (Some(5), Some(0))
    );
    for row in rows {
        assert_eq!(row["picture"]["loaded"], true, "{row}");
    }
    assert!(
        image::open(&shot).unwrap().height() > 400,
        "a screenshot of the page"
    );
}

//! `sim_speed` runs without Stage (CI has none): a short run in our own hall, one thread and
//! two, which must agree robot for robot, and a moment of the 1 024-robot swarm. 40 robots:
//! a step shares its scans among threads only from 32.

use std::process::Command;

#[test]
fn a_short_run_without_stage_agrees_on_any_number_of_threads() {
    let out = Command::new(env!("CARGO_BIN_EXE_sim_speed"))
        .args([
            "--stage-worlds",
            "/nonexistent",
            "--robots",
            "40",
            "--seconds",
            "1",
        ])
        .args(["--threads", "2", "--swarm-seconds", "0.2"])
        .output()
        .expect("sim_speed runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Both passes reported, with the same robots' end poses (the bench fails otherwise).
    let digest = |prefix: &str| {
        text.lines()
            .find(|l| l.starts_with(prefix))
            .and_then(|l| l.split('(').nth(1))
            .map(|d| d[..16].to_string())
            .unwrap_or_else(|| panic!("no '{prefix}' line in:\n{text}"))
    };
    assert_eq!(digest("one thread:"), digest("2 threads:"));
    assert!(text.contains("swarm1024"), "{text}");
}

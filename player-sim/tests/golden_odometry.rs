//! player-sim's odometry and position control against Stage 4.3's, measured by
//! `golden/measure.sh odometry` in our `golden/odometry.world`: the pose position2d reports
//! step by step under fixed commands (`localization "odom"` with `odom_error` and
//! `localization_origin`, a differential and an omnidirectional robot: Stage's turn error read
//! in degrees, its sideways sign), and the true path of a robot steered by position commands.
//! Each is compared from one sampled step to each later one, as the drives of tests/golden.rs.

use std::path::{Path, PathBuf};

use player_sim::sim::{Command, Simulation, wrap};
use player_sim::world::{Pose, World};
use serde_json::Value;

fn here() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("golden")
}

/// The golden file's header and its lines.
fn golden(name: &str) -> (Value, Vec<Value>) {
    let text = std::fs::read_to_string(here().join(format!("stage/{name}.jsonl"))).unwrap();
    let mut lines = text
        .lines()
        .map(|l| serde_json::from_str::<Value>(l).unwrap());
    let header = lines.next().unwrap();
    (header, lines.collect())
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|n| n.as_f64().unwrap())
        .collect()
}

fn samples(line: &Value) -> Vec<[f64; 4]> {
    line["samples"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            let n = numbers(s);
            [n[0], n[1], n[2], n[3]]
        })
        .collect()
}

fn pose(s: &[f64; 4]) -> Pose {
    Pose {
        x: s[1],
        y: s[2],
        a: s[3],
    }
}

fn world() -> World {
    World::load(&here().join("odometry.world")).unwrap()
}

/// How far apart two poses are: metres and degrees.
fn apart(a: Pose, b: Pose) -> (f64, f64) {
    (
        (a.x - b.x).hypot(a.y - b.y),
        wrap(a.a - b.a).abs().to_degrees(),
    )
}

#[test]
fn odometry_reads_step_by_step_as_stages() {
    let (_, drives) = golden("ours-odometry-odom");
    let mut started = [false; 2];
    let (mut worst_m, mut worst_deg) = (0.0f64, 0.0f64);
    for drive in &drives {
        let i = drive["index"].as_u64().unwrap() as usize;
        let c = numbers(&drive["command"]);
        let dt = drive["interval"].as_f64().unwrap();
        let samples = samples(drive);
        if !started[i] {
            // Before any motion: the start pose in the frame of localization_origin.
            let sim = Simulation::new(world());
            let (m, deg) = apart(sim.reported_pose(i), pose(&samples[0]));
            assert!(
                m < 1e-9 && deg < 1e-6,
                "robot {i} starts at {:?}",
                samples[0]
            );
            started[i] = true;
        }
        let first = samples
            .iter()
            .position(|s| pose(s) != pose(&samples[0]))
            .expect("a drive that moved");
        let from = samples[first];
        for to in &samples[first + 1..] {
            let mut sim = Simulation::new(world());
            sim.robots[i].estimate = pose(&from);
            sim.robots[i].command = Command::Velocity {
                vx: c[0],
                vy: c[1],
                va: c[2],
            };
            for _ in 0..((to[0] - from[0]) / dt).round() as usize {
                sim.step();
            }
            let (m, deg) = apart(sim.reported_pose(i), pose(to));
            worst_m = worst_m.max(m);
            worst_deg = worst_deg.max(deg);
        }
    }
    println!(
        "odometry, worst: {:.4} mm, {worst_deg:.5} degrees",
        worst_m * 1000.0
    );
    assert!(
        worst_m < 1e-4 && worst_deg < 1e-3,
        "{worst_m} m, {worst_deg} degrees"
    );
}

#[test]
fn position_control_steers_as_stages() {
    let (header, goals) = golden("ours-odometry-goto");
    let robot = header["robot"].as_str().unwrap();
    let (mut worst_m, mut worst_deg) = (0.0f64, 0.0f64);
    for goal in &goals {
        let g = numbers(&goal["goal"]);
        let target = Pose {
            x: g[0],
            y: g[1],
            a: g[2],
        };
        let dt = goal["interval"].as_f64().unwrap();
        let samples = samples(goal);
        let first = samples
            .iter()
            .position(|s| pose(s) != pose(&samples[0]))
            .expect("a goal that moved the robot");
        let from = samples[first];
        for to in &samples[first + 1..] {
            let mut sim = Simulation::new(world());
            let i = sim.robot_index(robot).unwrap();
            sim.robots[i].pose = pose(&from);
            // Where Stage's controller last saw the robot is a step before, not sampled (Player
            // answers a request every few steps): taken as where it is.
            sim.robots[i].estimate = pose(&from);
            sim.robots[i].command = Command::GoTo { target };
            for _ in 0..((to[0] - from[0]) / dt).round() as usize {
                sim.step();
            }
            let (m, deg) = apart(sim.robots[i].pose, pose(to));
            worst_m = worst_m.max(m);
            worst_deg = worst_deg.max(deg);
        }
    }
    println!(
        "position control, worst: {:.1} cm, {worst_deg:.2} degrees",
        worst_m * 100.0
    );
    // Well within the drive tolerance (a step: 6 cm, 3.5 degrees); steering from
    // where the robot is rather than where it was a step before, 4.1 cm and 2.5 degrees.
    assert!(
        worst_m <= 0.01 && worst_deg <= 1.0,
        "{worst_m} m, {worst_deg} degrees"
    );
}

//! The pruned ray casting (nearby boxes, per-ray bounding-circle tests) reads exactly what
//! testing every box against every beam reads.

use std::path::Path;

use player_sim::sim::{Command, Simulation, ranger_scan, ranger_scan_exhaustive};
use player_sim::world::{Pose, World};

fn load(name: &str) -> Simulation {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../stage-worlds")
        .join(name);
    Simulation::new(World::load(&path).unwrap())
}

fn assert_same_scans(sim: &Simulation) -> usize {
    let mut nearer_than_max = 0;
    for (robot, spec) in sim.world.robots.iter().enumerate() {
        for ranger in &spec.rangers {
            let pruned = ranger_scan(sim, robot, ranger);
            let reference = ranger_scan_exhaustive(sim, robot, ranger);
            assert_eq!(pruned.len(), reference.len());
            for (i, (a, b)) in pruned.iter().zip(&reference).enumerate() {
                assert!((a - b).abs() < 1e-9, "robot {robot} beam {i}: {a} vs {b}");
            }
            let max = ranger.sensors[0].max_range;
            nearer_than_max += reference.iter().filter(|&&r| r < max - 1e-6).count();
        }
    }
    nearer_than_max
}

#[test]
fn the_swarm_reads_the_same_with_and_without_pruning() {
    let mut sim = load("swarm.world");
    // Crowd the robots: a 16 x 16 block with 0.9 m spacing, so beams meet many robots.
    for (i, r) in sim.robots.iter_mut().enumerate() {
        r.pose = Pose {
            x: -7.0 + 0.9 * (i % 16) as f64,
            y: -7.0 + 0.9 * (i / 16) as f64,
            a: 0.37 * i as f64,
        };
        r.command = Command::Velocity {
            vx: 0.2,
            vy: 0.0,
            va: 0.3,
        };
    }
    let hits = assert_same_scans(&sim);
    assert!(hits > 10_000, "the beams hit robots: {hits}");
    for _ in 0..5 {
        sim.step();
    }
    assert_same_scans(&sim);
}

#[test]
fn the_multirobot_world_reads_the_same_with_and_without_pruning() {
    let mut sim = load("multirobot.world");
    for _ in 0..3 {
        sim.step();
        assert_same_scans(&sim);
    }
}

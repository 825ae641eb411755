//! The robots' spatial index changes nothing that is read or simulated: scans over a random
//! arrangement (robots straddling cell borders, stacked, outside the hall) read what testing
//! every robot against every beam reads, and robots driving into a crowd never overlap.

use std::path::Path;

use player_sim::sim::{Command, Simulation, ranger_returns, ranger_scan_exhaustive};
use player_sim::world::{Pose, World};

fn swarm() -> Simulation {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/swarm.world");
    Simulation::new(World::load(&path).unwrap())
}

/// A small deterministic generator (xorshift): the same arrangement every run.
fn randoms(mut state: u64) -> impl FnMut() -> f64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn assert_scans_match_exhaustive(sim: &Simulation) -> usize {
    let mut hits = 0;
    for (robot, spec) in sim.world.robots.iter().enumerate() {
        for ranger in &spec.rangers {
            let indexed = ranger_returns(sim, robot, ranger);
            let reference = ranger_scan_exhaustive(sim, robot, ranger);
            assert_eq!(indexed.ranges.len(), reference.len());
            for (i, (a, b)) in indexed.ranges.iter().zip(&reference).enumerate() {
                assert!((a - b).abs() < 1e-9, "robot {robot} beam {i}: {a} vs {b}");
            }
            let max = ranger.sensors[0].max_range;
            hits += reference.iter().filter(|&&r| r < max - 1e-6).count();
        }
    }
    hits
}

fn scatter(sim: &mut Simulation, seed: u64) {
    let mut next = randoms(seed);
    for (i, r) in sim.robots.iter_mut().enumerate() {
        r.pose = match i % 10 {
            // Outside the 64 m hall.
            0 => Pose {
                x: 120.0 * next() - 60.0,
                y: 40.0 + 10.0 * next(),
                a: 6.0 * next(),
            },
            // On whole and half metres, where cell borders are likely.
            1 | 2 => Pose {
                x: (30.0 * next() - 15.0).round() / 2.0,
                y: (30.0 * next() - 15.0).round() / 2.0,
                a: 6.0 * next(),
            },
            // A crowd, robots overlapping one another.
            _ => Pose {
                x: 20.0 * next() - 10.0,
                y: 20.0 * next() - 10.0,
                a: 6.0 * next(),
            },
        };
    }
}

#[test]
fn a_random_arrangement_reads_the_same_with_the_index() {
    let mut sim = swarm();
    for (k, seed) in [1, 0xC0FFEE, 77, 5].into_iter().enumerate() {
        scatter(&mut sim, seed);
        // Read both ways: scan by scan, and all in one sensing scope (the index checked once,
        // on entering, for robots that moved since the last scans).
        let hits = if k % 2 == 0 {
            assert_scans_match_exhaustive(&sim)
        } else {
            sim.sensing(assert_scans_match_exhaustive)
        };
        assert!(hits > 5_000, "the beams hit robots: {hits}");
    }
}

#[test]
fn robots_driving_into_a_crowd_never_overlap() {
    let mut sim = swarm();
    // A 16 x 16 block 0.6 m apart (bodies 0.44 x 0.38: not touching), all turning and driving.
    for (i, r) in sim.robots.iter_mut().enumerate() {
        r.pose = Pose {
            x: -4.5 + 0.6 * (i % 16) as f64,
            y: -4.5 + 0.6 * (i / 16) as f64,
            a: 0.0,
        };
        r.command = Command::Velocity {
            vx: 0.5,
            vy: 0.0,
            va: 0.2 + 0.05 * (i % 5) as f64,
        };
    }
    let mut stalls = 0;
    for step in 0..30 {
        sim.step();
        stalls += sim.robots.iter().filter(|r| r.stall).count();
        for i in 0..sim.robots.len() {
            let a = sim.footprint(i, sim.robots[i].pose);
            for j in i + 1..sim.robots.len() {
                let b = sim.footprint(j, sim.robots[j].pose);
                assert!(!a.overlaps(&b), "step {step}: robots {i} and {j} overlap");
            }
        }
        if step % 10 == 0 {
            assert_scans_match_exhaustive(&sim);
        }
    }
    assert!(stalls > 100, "the crowd bumps: {stalls} stalls");
}

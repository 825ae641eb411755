//! Seeded range noise: the same seed gives the same readings, another seed others, and the
//! readings scatter around the true range with the asked standard deviation.

use std::path::Path;

use player_sim::sim::{Noise, Simulation, ranger_scan};
use player_sim::world::{Pose, World};

/// simple.world's robot 2 m (laser to wall) from the east wall, with noise.
fn noisy(seed: u64, range_sd: f64) -> Simulation {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/simple.world");
    let mut sim = Simulation::new(World::load(&path).unwrap());
    sim.robots[0].pose = Pose {
        x: 2.7,
        y: 0.0,
        a: 0.0,
    };
    sim.noise = Noise { seed, range_sd };
    sim
}

/// The straight-ahead reading over `steps` steps.
fn ahead(sim: &mut Simulation, steps: usize) -> Vec<f64> {
    let laser = sim.world.robots[0].rangers[0].clone();
    (0..steps)
        .map(|_| {
            sim.step();
            ranger_scan(sim, 0, &laser)[90]
        })
        .collect()
}

#[test]
fn a_seed_reproduces_the_noise_and_the_noise_has_the_asked_spread() {
    let first = ahead(&mut noisy(42, 0.05), 400);
    assert_eq!(
        first,
        ahead(&mut noisy(42, 0.05), 400),
        "same seed, same run"
    );
    assert_ne!(first, ahead(&mut noisy(43, 0.05), 400), "another seed");
    let mean = first.iter().sum::<f64>() / first.len() as f64;
    let sd = (first.iter().map(|r| (r - mean).powi(2)).sum::<f64>() / first.len() as f64).sqrt();
    assert!((mean - 2.0).abs() < 0.01, "mean {mean}");
    assert!((sd - 0.05).abs() < 0.01, "sd {sd}");
    // Without noise the seed changes nothing.
    assert_eq!(ahead(&mut noisy(1, 0.0), 5), ahead(&mut noisy(2, 0.0), 5));
    assert!(
        ahead(&mut noisy(1, 0.0), 5)
            .iter()
            .all(|r| (r - 2.0).abs() < 0.02)
    );
}

#[test]
fn beams_that_hit_nothing_read_the_maximum_and_noisy_ones_stay_within_range() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("open.world");
    // No walls; one box straight ahead whose face is 7.95 m from the laser (8 m range).
    std::fs::write(
        &path,
        "position( name \"r\" size [ 0.4 0.4 0.2 ] ranger( sensor( range [ 0 8 ] fov 180 samples 181 ) ) )\n\
         model( name \"far\" pose [ 8.15 0 0 0 ] size [ 0.4 0.4 0.5 ] )\n",
    )
    .unwrap();
    let mut sim = Simulation::new(World::load(&path).unwrap());
    let laser = sim.world.robots[0].rangers[0].clone();
    let mut ahead = Vec::new();
    for seed in 0..50 {
        sim.noise = Noise {
            seed,
            range_sd: 0.3,
        };
        let scan = ranger_scan(&sim, 0, &laser);
        assert!(scan[..80].iter().all(|&r| r == 8.0), "nothing to the right");
        assert!(scan[100..].iter().all(|&r| r == 8.0), "nothing to the left");
        assert!((0.0..=8.0).contains(&scan[90]));
        ahead.push(scan[90]);
    }
    assert!(
        ahead.iter().any(|&r| r < 7.9),
        "the box reading is noisy: {ahead:?}"
    );
}

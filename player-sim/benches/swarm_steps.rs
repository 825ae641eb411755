//! Simulation steps per second of `stage-worlds/swarm.world` (256 robots with lasers) and
//! `swarm1024.world` (1 024), each step
//! with what a served step computes: motion and collisions of every robot, then every laser's
//! scan (as when every laser is subscribed). The target is 10 steps/s on 2 cores.
//! "unpruned" casts every beam against every robot, as player-sim did before the pruning: the
//! ratio of the two is the pruning's gain.
//!
//! `cargo bench -p player-sim --bench swarm_steps -- --warm-up-time 1 --measurement-time 3`

use std::path::Path;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use player_sim::sim::{Command, Simulation, ranger_scan, ranger_scan_exhaustive};
use player_sim::world::{RangerSpec, World};

fn swarm() -> Simulation {
    swarm_of("swarm.world")
}

fn swarm_of(file: &str) -> Simulation {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../stage-worlds")
        .join(file);
    let mut sim = Simulation::new(World::load(&path).expect("the swarm world loads"));
    // Every robot drives and turns, so collision checks run for all of them.
    for (i, robot) in sim.robots.iter_mut().enumerate() {
        robot.command = Command::Velocity {
            vx: 0.3,
            vy: 0.0,
            va: 0.1 + 0.01 * (i % 7) as f64,
        };
    }
    sim
}

type Scan = fn(&Simulation, usize, &RangerSpec) -> Vec<f64>;

/// One served step: motion, then every ranger's readings by `scan`.
fn step_with_sensors(sim: &mut Simulation, scan: Scan) -> usize {
    sim.step();
    // As a served step reads them: in one sensing scope.
    sim.sensing(|sim| {
        let mut readings = 0;
        for (robot, spec) in sim.world.robots.iter().enumerate() {
            for ranger in &spec.rangers {
                readings += scan(sim, robot, ranger).len();
            }
        }
        readings
    })
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("swarm.world");
    group.throughput(Throughput::Elements(1));
    group.sample_size(10);
    let mut sim = swarm();
    group.bench_function("step with 256 laser scans", |b| {
        b.iter(|| std::hint::black_box(step_with_sensors(&mut sim, ranger_scan)))
    });
    // The same scans testing every robot against every beam: the unpruned baseline.
    let mut sim = swarm();
    group.bench_function("step with 256 laser scans, unpruned", |b| {
        b.iter(|| std::hint::black_box(step_with_sensors(&mut sim, ranger_scan_exhaustive)))
    });
    let mut sim = swarm();
    group.bench_function("step without sensors", |b| b.iter(|| sim.step()));
    group.finish();
    // The scale target: 1 024 robots, each scan pruned to the boxes near its robot.
    let mut group = c.benchmark_group("swarm1024.world");
    group.throughput(Throughput::Elements(1));
    group.sample_size(10);
    let mut sim = swarm_of("swarm1024.world");
    group.bench_function("step with 1024 laser scans", |b| {
        b.iter(|| std::hint::black_box(step_with_sensors(&mut sim, ranger_scan)))
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

//! Does player-sim keep up with swarm.world served for real? Serves its 256 robots on free
//! ports at real time (10 Hz), subscribes every laser with its own client over TCP (as 256
//! Player clients would), and reports the simulated steps per wall second and the scans the
//! clients received. Clients and server share the machine's cores, so this is a lower bound.
//!
//! `cargo run --release -p player-sim --example swarm_served -- [SECONDS] [SPEEDUP]`

use std::path::Path;
use std::time::{Duration, Instant};

use anyhow::{Context, Result};
use player_proto::client::{Client, ClientOptions};
use player_sim::serve::{ServeOptions, serve};
use player_sim::served::from_cfg;
use player_sim::sim::Simulation;
use player_sim::world::World;

fn main() -> Result<()> {
    let mut args = std::env::args().skip(1);
    let seconds: f64 = args.next().map_or(Ok(5.0), |s| s.parse())?;
    let speedup: f64 = args.next().map_or(Ok(1.0), |s| s.parse())?;
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/swarm.world");
    let world = World::load(&path)?;
    let devices = from_cfg(&path.with_extension("cfg"), &world, &mut Vec::new())?;
    let options = ServeOptions {
        speedup,
        free_ports: true,
        ..ServeOptions::default()
    };
    let running = serve(Simulation::new(world), devices, options)?;
    let mut clients = Vec::new();
    for &(_, port) in &running.ports {
        let client = Client::connect("127.0.0.1", port, ClientOptions::default())
            .with_context(|| format!("connecting to {port}"))?;
        client.laser(0).subscribe()?;
        clients.push(client);
    }
    let scan_id = |c: &Client| c.laser(0).scan().map_or(0, |(s, _)| s.id);
    let (steps0, ids0): (u64, Vec<u32>) = (
        running.sim.lock().expect("simulation").steps,
        clients.iter().map(scan_id).collect(),
    );
    let started = Instant::now();
    std::thread::sleep(Duration::from_secs_f64(seconds));
    let elapsed = started.elapsed().as_secs_f64();
    let steps = running.sim.lock().expect("simulation").steps - steps0;
    let advanced: Vec<u32> = clients
        .iter()
        .zip(&ids0)
        .map(|(c, &before)| scan_id(c).saturating_sub(before))
        .collect();
    let slowest = advanced.iter().min().copied().unwrap_or(0);
    let asked = if speedup > 0.0 {
        format!("{:.1}", 10.0 * speedup)
    } else {
        "as fast as possible".to_string()
    };
    println!(
        "{} lasers subscribed; {:.1} steps/s simulated (asked {asked}); newest scan advanced by at least {slowest} per client in {elapsed:.1} s",
        clients.len(),
        steps as f64 / elapsed,
    );
    Ok(())
}

//! A digest of everything a world's devices send over some steps, as Player wire bytes: run it
//! before and after a change to the simulation or the encoding, and the two digests agree when
//! the change left every scan, pose and message byte as it was. The robots drive and turn (as
//! in the `swarm_steps` bench) so that motion, collisions and moving sensors are all covered.
//!
//! `cargo run --release -p player-sim --example step_digest -- WORLD [STEPS] [RANGE_NOISE]`
//! e.g. `-- stage-worlds/swarm1024.world 30` (prints one digest per ten steps and the last).

use std::hash::{DefaultHasher, Hasher};
use std::path::PathBuf;

use anyhow::{Context, Result};
use player_proto::message::Message;
use player_proto::wire::MsgType;
use player_sim::devices::SimDevice;
use player_sim::served::devices_beside;
use player_sim::sim::{Command, Noise, Simulation};
use player_sim::world::World;

fn main() -> Result<()> {
    let mut args = std::env::args().skip(1);
    let path: PathBuf = args.next().context("WORLD")?.into();
    let steps: u64 = args.next().map_or(Ok(30), |s| s.parse())?;
    let range_sd: f64 = args.next().map_or(Ok(0.0), |s| s.parse())?;
    let world = World::load(&path)?;
    let devices = devices_beside(&path, &world, &mut Vec::new())?;
    let mut sim = Simulation::new(world);
    sim.noise = Noise { seed: 7, range_sd };
    for (i, robot) in sim.robots.iter_mut().enumerate() {
        robot.command = Command::Velocity {
            vx: 0.3,
            vy: 0.0,
            va: 0.1 + 0.01 * (i % 7) as f64,
        };
    }
    let mut digest = DefaultHasher::new();
    let mut messages = 0u64;
    for step in 1..=steps {
        sim.step();
        let id = u32::try_from(sim.steps).unwrap_or(u32::MAX);
        // As a served step reads them: in one sensing scope.
        sim.sensing(|sim| {
            for device in &devices {
                for (subtype, body) in SimDevice::data(sim, &device.source, id) {
                    let message = Message::new(device.addr(), MsgType::Data, subtype, body);
                    digest.write(&message.to_bytes());
                    messages += 1;
                }
            }
        });
        if step % 10 == 0 || step == steps {
            println!(
                "step {step}: {messages} messages, digest {:016x}",
                digest.finish()
            );
        }
    }
    Ok(())
}

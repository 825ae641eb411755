//! Saves what a robot's camera sees as a PNG, to look at the simulated camera without a viewer:
//! `cargo run -p player-sim --example camera_snapshot -- stage-worlds/multirobot.world r0 out.png`

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use player_sim::sim::{Simulation, render_camera};
use player_sim::world::World;

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [world, robot, out] = args.as_slice() else {
        bail!("usage: camera_snapshot WORLD ROBOT OUT.png");
    };
    let sim = Simulation::new(World::load(&PathBuf::from(world))?);
    let index = sim
        .robot_index(robot)
        .with_context(|| format!("no robot {robot:?} in {world}"))?;
    let Some(camera) = sim.world.robots[index].cameras.first() else {
        bail!("{robot} has no camera");
    };
    let frame = render_camera(&sim, index, camera);
    image::save_buffer(
        out,
        &frame.rgb,
        frame.width,
        frame.height,
        image::ExtendedColorType::Rgb8,
    )?;
    println!("{out}: {}x{}", frame.width, frame.height);
    Ok(())
}

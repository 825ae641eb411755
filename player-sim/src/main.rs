//! `player-sim WORLD` — serve a simulated Stage world over the Player protocol.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::Parser;
use player_sim::serve::{ServeOptions, serve};
use player_sim::served::{default_devices, from_cfg, shift_ports};
use player_sim::sim::Simulation;
use player_sim::world::World;

/// Serve a simulated Stage world over the Player protocol.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Cli {
    /// A Stage world file, e.g. stage-worlds/multirobot.world.
    world: PathBuf,

    /// The Player .cfg naming each robot's devices and ports; by default the world's name with
    /// .cfg, if there is one, else one port per robot from --port-base.
    #[arg(long)]
    cfg: Option<PathBuf>,

    /// Serve the lowest port on this one, the others shifted alike.
    #[arg(long)]
    port_base: Option<u16>,

    /// Simulated seconds per real second (0: as fast as possible).
    #[arg(long, default_value_t = 1.0)]
    speedup: f64,

    /// Seed of the simulation's randomness (the simulation is deterministic for a seed).
    #[arg(long, default_value_t = 0)]
    seed: u64,

    /// Step N times, then exit.
    #[arg(long, value_name = "N")]
    headless_once: Option<u64>,

    /// Address to listen on.
    #[arg(long, default_value = "127.0.0.1")]
    bind: std::net::IpAddr,
}

fn main() -> ExitCode {
    player_proto::logging::init("info");
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("player-sim: {e:#}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: Cli) -> Result<()> {
    anyhow::ensure!(
        cli.speedup >= 0.0 && cli.speedup.is_finite(),
        "--speedup must be 0 or more"
    );
    let world = World::load(&cli.world)?;
    let mut ignored = world.ignored.clone();
    let cfg = cli
        .cfg
        .clone()
        .or_else(|| Some(cli.world.with_extension("cfg")).filter(|p| p.exists()));
    let mut devices = match &cfg {
        Some(path) => from_cfg(path, &world, &mut ignored)
            .with_context(|| format!("reading {}", path.display()))?,
        None => default_devices(&world, cli.port_base.unwrap_or(6665)),
    };
    if let Some(base) = cli.port_base {
        shift_ports(&mut devices, base);
    }
    for note in &ignored {
        tracing::warn!("{note}");
    }
    let robots = world.robots.len();
    // The simulation has no noise yet, so the seed only has to be accepted; it is reported so
    // that runs can be reproduced once it matters.
    tracing::info!(
        seed = cli.seed,
        "{robots} robots, {} devices",
        devices.len()
    );
    let options = ServeOptions {
        bind: cli.bind,
        speedup: cli.speedup,
        max_steps: cli.headless_once,
        free_ports: false,
    };
    let running = serve(Simulation::new(world), devices, options)?;
    let ports: Vec<String> = running.ports.iter().map(|(_, p)| p.to_string()).collect();
    eprintln!(
        "player-sim: serving {} on port(s) {}",
        cli.world.display(),
        ports.join(", ")
    );
    running.wait();
    Ok(())
}

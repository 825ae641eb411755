//! `player-sim WORLD` — serve a simulated Stage world over the Player protocol.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::Parser;
use player_sim::serve::{ServeOptions, serve};
use player_sim::served::{DEFAULT_PORT, cfgs_beside, default_devices, from_cfgs, shift_ports};
use player_sim::sim::{Noise, Simulation};
use player_sim::world::World;

/// Serve a simulated Stage world over the Player protocol.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Cli {
    /// A Stage world file, e.g. stage-worlds/multirobot.world.
    world: PathBuf,

    /// The Player .cfg naming each robot's devices and ports; by default the world's name with
    /// .cfg (and then with -nav.cfg, a navigation half), if there is one, else one port per
    /// robot from --port-base. Give it again for the .cfg of a second `player` process
    /// (navigation drivers reaching Stage's devices through `passthrough`): player-sim serves
    /// the ports of both.
    #[arg(long)]
    cfg: Vec<PathBuf>,

    /// Serve the lowest port on this one, the others shifted alike.
    #[arg(long)]
    port_base: Option<u16>,

    /// Simulated seconds per real second (0: as fast as possible).
    #[arg(long, default_value_t = 1.0)]
    speedup: f64,

    /// Seed of the sensor noise and of Stage's wander controller (how long a robot keeps
    /// turning): a run is reproduced exactly by its seed.
    #[arg(long, default_value_t = 0)]
    seed: u64,

    /// Standard deviation, in metres, of Gaussian noise on every ranger, laser and sonar
    /// reading that hits something (0: exact readings).
    #[arg(long, default_value_t = 0.0, value_name = "METRES")]
    range_noise: f64,

    /// Step N times, then exit.
    #[arg(long, value_name = "N")]
    headless_once: Option<u64>,

    /// Address to listen on.
    #[arg(long, default_value = "127.0.0.1")]
    bind: std::net::IpAddr,
}

fn main() -> ExitCode {
    player_tools::logging::init("info");
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
    anyhow::ensure!(
        cli.range_noise >= 0.0 && cli.range_noise.is_finite(),
        "--range-noise must be 0 or more metres"
    );
    let world = World::load(&cli.world)?;
    let mut ignored = world.ignored.clone();
    let mut cfgs = cli.cfg.clone();
    if cfgs.is_empty() {
        cfgs = cfgs_beside(&cli.world);
    }
    let mut devices = if cfgs.is_empty() {
        default_devices(&world, cli.port_base.unwrap_or(DEFAULT_PORT))
    } else {
        let paths: Vec<&Path> = cfgs.iter().map(PathBuf::as_path).collect();
        from_cfgs(&paths, &world, &mut ignored).context("reading the .cfg")?
    };
    if let Some(base) = cli.port_base {
        shift_ports(&mut devices, base);
    }
    for note in &ignored {
        tracing::warn!("{note}");
    }
    let robots = world.robots.len();
    tracing::info!(
        seed = cli.seed,
        range_noise = cli.range_noise,
        "{robots} robots, {} devices",
        devices.len()
    );
    let options = ServeOptions {
        bind: cli.bind,
        speedup: cli.speedup,
        max_steps: cli.headless_once,
        free_ports: false,
    };
    let mut sim = Simulation::new(world);
    sim.noise = Noise {
        seed: cli.seed,
        range_sd: cli.range_noise,
    };
    let running = serve(sim, devices, options)?;
    let ports: Vec<String> = running.ports.iter().map(|(_, p)| p.to_string()).collect();
    eprintln!(
        "player-sim: serving {} on port(s) {}",
        cli.world.display(),
        ports.join(", ")
    );
    running.wait();
    Ok(())
}

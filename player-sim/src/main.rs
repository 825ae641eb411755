//! `player-sim WORLD` — serve a simulated Stage world over the Player protocol.
//! `player-sim --replay FILE` — serve a recording as the Player servers it was recorded from.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;

use anyhow::{Context, Result};
use clap::Parser;
use player_sim::replay::ReplayOptions;
use player_sim::serve::{LockstepOptions, ServeOptions, serve};
use player_sim::served::{devices_beside, from_cfgs, shift_ports};
use player_sim::sim::{Noise, Simulation};
use player_sim::sim_record::SimRecording;
use player_sim::world::{World, ignored_summary};

/// Serve a simulated Stage world over the Player protocol.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Cli {
    /// A Stage world file, e.g. stage-worlds/multirobot.world.
    #[arg(required_unless_present = "replay", conflicts_with = "replay")]
    world: Option<PathBuf>,

    /// Serve this recording (pv3d --record, playerrecord) instead of a world: its servers on
    /// their recorded ports (or from --port-base), playback controlled by a `log` device.
    #[arg(long, value_name = "FILE")]
    replay: Option<PathBuf>,

    /// Replay speed: recorded seconds per real second.
    #[arg(long, default_value_t = 1.0, requires = "replay")]
    speed: f64,

    /// Start the replay paused.
    #[arg(long, requires = "replay")]
    paused: bool,

    /// Start the replay again when it ends.
    #[arg(long = "loop", requires = "replay")]
    looping: bool,

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

    /// Simulated seconds per real second (0: as fast as possible); by default the world's
    /// `speedup` (Stage's, 0 or less as fast as possible), else 1, and 0 in lockstep, where the
    /// clients set the pace.
    #[arg(long)]
    speedup: Option<f64>,

    /// Seed of the sensor noise and of Stage's wander controller (how long a robot keeps
    /// turning): a run is reproduced exactly by its seed.
    #[arg(long, default_value_t = 0)]
    seed: u64,

    /// Standard deviation, in metres, of Gaussian noise on every ranger, laser and sonar
    /// reading that hits something (0: exact readings).
    #[arg(long, default_value_t = 0.0, value_name = "METRES")]
    range_noise: f64,

    /// Step in lockstep with the clients that drive robots: a step is taken once every
    /// connection that has commanded a device sent its command for the step, so a run depends
    /// on what the programs decide, not on how fast the machine runs them. A --speedup given
    /// still caps the pace.
    #[arg(long)]
    lockstep: bool,

    /// How long a lockstep step waits for a client's command, wall-clock seconds; a client that
    /// misses it is not waited for until it commands again (0: wait for ever).
    #[arg(
        long,
        default_value_t = 5.0,
        value_name = "SECONDS",
        requires = "lockstep"
    )]
    patience: f64,

    /// Record every robot's devices, every step, stamped with simulated time (MCAP when the
    /// name ends in .mcap, else .prec): a lockstep run's recording is the same, byte for byte,
    /// every time.
    #[arg(long, value_name = "FILE", conflicts_with = "replay")]
    record: Option<PathBuf>,

    /// Simulate this many seconds, then exit (a whole recording: one stopped by Ctrl-C reads
    /// up to its last whole chunk).
    #[arg(long, value_name = "SECONDS", conflicts_with = "headless_once")]
    until: Option<f64>,

    /// Step N times, then exit.
    #[arg(long, value_name = "N")]
    headless_once: Option<u64>,

    /// Address to listen on.
    #[arg(long, default_value = "127.0.0.1")]
    bind: std::net::IpAddr,
}

fn main() -> ExitCode {
    program_edge::logging::init("info");
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("player-sim: {e:#}");
            ExitCode::FAILURE
        }
    }
}

/// Simulated seconds per real second: `--speedup` when given; in lockstep as fast as the
/// clients answer; else the world's own `speedup` (Stage honours it only in its window: here it
/// holds headless too, a Stage `speedup` of 0 or -1 being as fast as possible), else real time.
fn pace(given: Option<f64>, lockstep: bool, world: Option<f64>) -> f64 {
    match (given, lockstep, world) {
        (Some(speedup), _, _) => speedup,
        (None, true, _) => 0.0,
        (None, false, Some(speedup)) if speedup.is_finite() => speedup.max(0.0),
        (None, false, _) => 1.0,
    }
}

fn run(cli: Cli) -> Result<()> {
    if let Some(path) = &cli.replay {
        return replay(path, &cli);
    }
    let Some(world_path) = &cli.world else {
        anyhow::bail!("name a world file, or a recording with --replay");
    };
    if let Some(speedup) = cli.speedup {
        anyhow::ensure!(
            speedup >= 0.0 && speedup.is_finite(),
            "--speedup must be 0 or more"
        );
    }
    anyhow::ensure!(
        cli.range_noise >= 0.0 && cli.range_noise.is_finite(),
        "--range-noise must be 0 or more metres"
    );
    anyhow::ensure!(
        cli.patience >= 0.0 && cli.patience.is_finite(),
        "--patience must be 0 (for ever) or more seconds"
    );
    let world = World::load(world_path)?;
    let speedup = pace(cli.speedup, cli.lockstep, world.speedup);
    let max_steps = match cli.until {
        Some(seconds) => {
            anyhow::ensure!(
                seconds >= 0.0 && seconds.is_finite(),
                "--until must be 0 or more simulated seconds"
            );
            Some((seconds / world.interval).round() as u64)
        }
        None => cli.headless_once,
    };
    let mut ignored = world.ignored.clone();
    let mut devices = if cli.cfg.is_empty() {
        devices_beside(world_path, &world, &mut ignored).context("reading the .cfg")?
    } else {
        let paths: Vec<&Path> = cli.cfg.iter().map(PathBuf::as_path).collect();
        from_cfgs(&paths, &world, &mut ignored).context("reading the .cfg")?
    };
    if let Some(base) = cli.port_base {
        shift_ports(&mut devices, base);
    }
    for note in &ignored {
        tracing::debug!("{note}");
    }
    if let Some(summary) = ignored_summary(&ignored) {
        tracing::warn!("{summary} (RUST_LOG=player_sim=debug says where)");
    }
    let robots = world.robots.len();
    tracing::info!(
        seed = cli.seed,
        range_noise = cli.range_noise,
        "{robots} robots, {} devices",
        devices.len()
    );
    // A lockstep run's recording is the same bytes every time: its MCAP chunks end when full,
    // not after a second of wall-clock time.
    let recorder = match &cli.record {
        Some(path) if cli.lockstep => Some(player_mcap::reproducible_recorder(path)),
        Some(path) => Some(player_mcap::recorder(path)),
        None => None,
    }
    .transpose()
    .with_context(|| {
        format!(
            "recording to {}",
            cli.record.as_deref().unwrap_or(Path::new("")).display()
        )
    })?;
    let options = ServeOptions {
        bind: cli.bind,
        speedup,
        max_steps,
        lockstep: cli.lockstep.then(|| LockstepOptions {
            patience: (cli.patience > 0.0).then(|| Duration::from_secs_f64(cli.patience)),
        }),
        record: recorder.as_ref().map(SimRecording::to),
        ..ServeOptions::default()
    };
    let mut sim = Simulation::new(world);
    sim.noise = Noise {
        seed: cli.seed,
        range_sd: cli.range_noise,
    };
    let running = serve(sim, devices, options)?;
    let ports: Vec<u16> = running.ports.iter().map(|&(_, p)| p).collect();
    eprintln!(
        "player-sim: serving {} on port(s) {}",
        world_path.display(),
        port_ranges(&ports)
    );
    running.wait();
    if let Some(recorder) = recorder {
        let stats = recorder.finish().context("finishing the recording")?;
        if let Some(path) = &cli.record {
            eprintln!(
                "player-sim: recorded {} records ({} bytes) to {}",
                stats.written,
                stats.bytes,
                path.display()
            );
        }
    }
    Ok(())
}

/// Ports as runs (`6665–7688`): a thousand robots make one line, not a screenful.
fn port_ranges(ports: &[u16]) -> String {
    let mut sorted = ports.to_vec();
    sorted.sort_unstable();
    let mut runs: Vec<(u16, u16)> = Vec::new();
    for port in sorted {
        match runs.last_mut() {
            Some((_, end)) if end.checked_add(1) == Some(port) => *end = port,
            _ => runs.push((port, port)),
        }
    }
    runs.iter()
        .map(|&(a, b)| {
            if a == b {
                a.to_string()
            } else {
                format!("{a}–{b}")
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

fn replay(path: &Path, cli: &Cli) -> Result<()> {
    let options = ReplayOptions {
        bind: cli.bind,
        port_base: cli.port_base,
        speed: cli.speed,
        paused: cli.paused,
        looping: cli.looping,
    };
    let replaying = player_sim::replay::replay(path, &options)?;
    if let Some(stopped) = &replaying.stopped {
        eprintln!(
            "player-sim: {}: plays up to where it stops: {stopped}",
            path.display()
        );
    }
    for s in &replaying.servers {
        eprintln!(
            "player-sim: replaying {}:{} on port {} (control: {}:{})",
            s.host, s.recorded_port, s.port, s.log.interf, s.log.index
        );
    }
    eprintln!(
        "player-sim: replaying {} ({:.1} s recorded) on {} port(s)",
        path.display(),
        replaying.clock.duration_ns() as f64 / 1e9,
        replaying.servers.len()
    );
    replaying.wait();
    Ok(())
}

#[cfg(test)]
mod tests {
    #[test]
    fn ports_are_said_as_runs() {
        assert_eq!(
            super::port_ranges(&[6667, 6665, 6666, 7000]),
            "6665–6667, 7000"
        );
        assert_eq!(super::port_ranges(&[6665]), "6665");
        assert_eq!(super::port_ranges(&[65534, 65535]), "65534–65535");
    }

    #[test]
    fn the_world_sets_the_pace_unless_told() {
        use super::pace;
        // Stage's simple.world says `speedup 0`; some worlds -1 (both: as fast as possible).
        assert_eq!(pace(None, false, Some(0.0)), 0.0);
        assert_eq!(pace(None, false, Some(-1.0)), 0.0);
        assert_eq!(pace(None, false, Some(4.0)), 4.0);
        assert_eq!(pace(None, false, None), 1.0);
        assert_eq!(pace(Some(2.0), false, Some(0.0)), 2.0);
        assert_eq!(pace(None, true, Some(4.0)), 0.0);
        assert_eq!(pace(Some(3.0), true, None), 3.0);
    }
}

//! How fast player-sim simulates, headless, with no Player server in the way: issue 34's run —
//! 100 Pioneers with SICK lasers wandering in Stage's cave (simple.world's bitmap) for 60
//! simulated seconds, as fast as possible — on one core and on every core; and the 1 024-robot
//! swarm (`stage-worlds/swarm1024.world`, every robot wandering on its laser) as a multiple of
//! real time. Every robot's laser is cast every step, as Stage's `wander` controller has it
//! cast (the controller subscribes to it): nothing Stage computes is skipped.
//!
//! The cave world is written by the bench itself beside Stage's `pioneer.inc`, `sick.inc`,
//! `map.inc` and `bitmaps/cave.png` (from `--stage-worlds`, the reference build's by default),
//! so that real Stage runs the very same file (`bench/stage-speed.sh`). Without Stage's worlds
//! (CI) the same robots are placed in our own hall (`stage-worlds/robots.inc`'s rover and
//! lidar), which still measures the simulator but is no comparison with Stage.
//!
//! `cargo run --release -p bench --bin sim_speed` (add `--seconds 2` for a short run).

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result, ensure};
use clap::Parser;
use player_sim::sim::Simulation;
use player_sim::world::{Controller, World};

#[derive(Parser, Debug)]
#[command(about = "player-sim's headless speed: Stage's cave with 100 wandering laser robots")]
struct Cli {
    /// Robots in the cave.
    #[arg(long, default_value_t = 100)]
    robots: usize,
    /// Simulated seconds of each run.
    #[arg(long, default_value_t = 60.0)]
    seconds: f64,
    /// Stage's worlds folder (pioneer.inc, sick.inc, map.inc, bitmaps/cave.png).
    #[arg(long, default_value = "/opt/ref/src/stage/worlds")]
    stage_worlds: PathBuf,
    /// Write the cave world (and what it includes) into this folder and exit: the world real
    /// Stage is timed on.
    #[arg(long)]
    write_world: Option<PathBuf>,
    /// Threads of the multi-core run (by default every core).
    #[arg(long)]
    threads: Option<usize>,
    /// Simulated seconds of the 1 024-robot swarm (0: not run).
    #[arg(long, default_value_t = 20.0)]
    swarm_seconds: f64,
}

fn main() -> Result<()> {
    let cli = Cli::parse();
    // The repository: the current folder when it holds our worlds (a copy elsewhere), else
    // where the bench was built.
    let repo = if Path::new("stage-worlds/swarm1024.world").is_file() {
        PathBuf::from(".")
    } else {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
    };
    let stage = cli.stage_worlds.join("bitmaps/cave.png").is_file();
    if let Some(dir) = &cli.write_world {
        ensure!(stage, "no Stage worlds in {}", cli.stage_worlds.display());
        let world = write_cave(dir, &cli.stage_worlds, cli.robots, cli.seconds)?;
        println!("{}", world.display());
        return Ok(());
    }
    let scratch = std::env::temp_dir().join(format!("sim_speed-{}", std::process::id()));
    let world = if stage {
        write_cave(&scratch, &cli.stage_worlds, cli.robots, cli.seconds)?
    } else {
        eprintln!(
            "no Stage worlds at {}: our own hall instead (no comparison with Stage)",
            cli.stage_worlds.display()
        );
        write_hall(&scratch, &repo.join("stage-worlds"), cli.robots)?
    };
    let loaded = World::load(&world).with_context(|| world.display().to_string())?;
    let _ = std::fs::remove_dir_all(&scratch);
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let threads = cli.threads.unwrap_or(cores).max(1);
    let what = if stage { "Stage's cave" } else { "our hall" };
    println!(
        "{} wandering laser robots in {what}, {} simulated s, {cores} cores",
        cli.robots, cli.seconds
    );
    let one = run(&loaded, cli.seconds, 1);
    println!("one thread:  {:.3} s wall ({})", one.wall, one.digest);
    let many = run(&loaded, cli.seconds, threads);
    println!(
        "{threads} threads:   {:.3} s wall ({}), {:.2}x one thread",
        many.wall,
        many.digest,
        one.wall / many.wall
    );
    ensure!(
        one.digest == many.digest,
        "threads changed the run: {} vs {}",
        one.digest,
        many.digest
    );
    if cli.swarm_seconds > 0.0 {
        let path = repo.join("stage-worlds/swarm1024.world");
        let mut swarm = World::load(&path).with_context(|| path.display().to_string())?;
        for robot in &mut swarm.robots {
            if !robot.rangers.is_empty() {
                robot.controller = Some(Controller::Wander { ranger: 0 });
            }
        }
        let swarm_run = run(&swarm, cli.swarm_seconds, threads);
        let stepping = swarm_run.wall - swarm_run.raster;
        println!(
            "swarm1024, every robot wandering on its laser, {threads} threads: {:.3} s wall for \
             {} simulated s: {:.1}x real time ({:.3} s of it the wall raster's build, once per \
             world: {:.1}x real time without it; {})",
            swarm_run.wall,
            cli.swarm_seconds,
            cli.swarm_seconds / swarm_run.wall,
            swarm_run.raster,
            cli.swarm_seconds / stepping,
            swarm_run.digest,
        );
    }
    Ok(())
}

struct Run {
    /// Seconds of the whole run, the wall raster's build (on the first step's first scan)
    /// included: as the run was always timed.
    wall: f64,
    /// Seconds of the raster's build alone, timed apart before the steps (a world's once).
    raster: f64,
    /// The robots' end poses, hashed: runs on any number of threads must agree.
    digest: String,
}

fn run(world: &World, seconds: f64, threads: usize) -> Run {
    let mut sim = Simulation::new(world.clone());
    sim.set_threads(threads);
    let steps = (seconds / world.interval).round() as u64;
    let started = Instant::now();
    sim.wall_raster();
    let raster = started.elapsed().as_secs_f64();
    for _ in 0..steps {
        sim.step();
    }
    let wall = started.elapsed().as_secs_f64();
    let mut hash = 0xcbf2_9ce4_8422_2325u64;
    for r in &sim.robots {
        for v in [r.pose.x, r.pose.y, r.pose.a] {
            hash = (hash ^ v.to_bits()).wrapping_mul(0x100_0000_01b3);
        }
    }
    Run {
        wall,
        raster,
        digest: format!("{hash:016x}"),
    }
}

/// Places for `n` robots in the free space of `floor`, at least 1 m apart and 0.5 m from any
/// wall, drawn from a fixed sequence so that every run (and Stage) gets the same ones.
fn places(world: &World, n: usize) -> Result<Vec<(f64, f64, f64)>> {
    let floor = world.floor.as_ref().context("the world has no floorplan")?;
    let (w, h) = (
        floor.width as f64 * floor.cell.0,
        floor.height as f64 * floor.cell.1,
    );
    let mut state = 0x5EED_0034u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut out: Vec<(f64, f64, f64)> = Vec::with_capacity(n);
    for _ in 0..200_000 {
        if out.len() == n {
            break;
        }
        let (x, y) = (floor.origin.0 + w * next(), floor.origin.1 + h * next());
        let a = 360.0 * next() - 180.0;
        let clear = (0..16).all(|k| {
            let t = k as f64 * std::f64::consts::TAU / 16.0;
            [0.0, 0.25, 0.5]
                .iter()
                .all(|r| !floor.occupied_at(x + r * t.cos(), y + r * t.sin()))
        });
        let apart = out.iter().all(|p| (p.0 - x).hypot(p.1 - y) >= 1.0);
        if clear && apart {
            out.push((x, y, a));
        }
    }
    ensure!(out.len() == n, "room for only {} robots", out.len());
    Ok(out)
}

/// Writes `dir/cave.world`: simple.world's cave and `n` wandering Pioneers with SICK lasers,
/// quitting after `seconds` (Stage headless runs as fast as it can, then quits).
fn write_cave(dir: &Path, stage_worlds: &Path, n: usize, seconds: f64) -> Result<PathBuf> {
    std::fs::create_dir_all(dir.join("bitmaps"))?;
    for file in ["pioneer.inc", "sick.inc", "map.inc", "bitmaps/cave.png"] {
        std::fs::copy(stage_worlds.join(file), dir.join(file))
            .with_context(|| format!("{}", stage_worlds.join(file).display()))?;
    }
    let head = format!(
        "include \"pioneer.inc\"\ninclude \"map.inc\"\ninclude \"sick.inc\"\n\
         quit_time {seconds}\npaused 0\nresolution 0.02\nspeedup -1\ninterval_sim 100\n\
         floorplan ( name \"cave\" size [16.000 16.000 0.800] pose [0 0 0 0] \
         bitmap \"bitmaps/cave.png\" )\n"
    );
    write_robots(dir, "cave.world", &head, n, |x, y, a| {
        format!(
            "pioneer2dx ( pose [ {x:.3} {y:.3} 0 {a:.1} ] sicklaser( pose [ 0 0 0 0 ] ) \
             ctrl \"wander\" localization \"gps\" )\n"
        )
    })
}

/// The same robots in our own hall, for a machine without Stage's worlds.
fn write_hall(dir: &Path, ours: &Path, n: usize) -> Result<PathBuf> {
    std::fs::create_dir_all(dir.join("bitmaps"))?;
    for file in ["robots.inc", "bitmaps/hall.png"] {
        std::fs::copy(ours.join(file), dir.join(file))?;
    }
    let head = "include \"robots.inc\"\ninterval_sim 100\n\
                floorplan ( name \"hall\" size [ 32 32 0.8 ] pose [ 0 0 0 0 ] \
                bitmap \"bitmaps/hall.png\" )\n";
    write_robots(dir, "hall.world", head, n, |x, y, a| {
        format!(
            "rover ( pose [ {x:.3} {y:.3} 0 {a:.1} ] lidar( pose [ 0.1 0 0 0 ] ) \
             ctrl \"wander\" )\n"
        )
    })
}

/// The world `head` alone, loaded to find free places, then written again with `n` robots.
fn write_robots(
    dir: &Path,
    name: &str,
    head: &str,
    n: usize,
    robot: impl Fn(f64, f64, f64) -> String,
) -> Result<PathBuf> {
    let path = dir.join(name);
    std::fs::write(&path, head)?;
    let empty = World::load(&path).with_context(|| path.display().to_string())?;
    let mut text = head.to_string();
    for (x, y, a) in places(&empty, n)? {
        text.push_str(&robot(x, y, a));
    }
    std::fs::write(&path, text)?;
    Ok(path)
}

//! A class graded: N students' programs of S simulated seconds each, through `player-grade`
//! (release, built beside it), first one at a time, then one per core — in the same run, on
//! the same class. Reports each pass's wall time, its ratio to running the programs one by one
//! in real time (N × S seconds: what Stage, which keeps to the clock, would take), and what the
//! second core adds. Every program drives by its laser for the whole time limit, so no run
//! ends early; the two passes must give the same scores (lockstep).
//!
//! `cargo build --release -p player-grade && cargo run --release -p bench --bin grade_class`

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use anyhow::{Context, Result, ensure};
use clap::Parser;

#[derive(Parser, Debug)]
#[command(about = "A class of robot programs graded, one at a time and on every core")]
struct Cli {
    #[arg(long, default_value_t = 30)]
    submissions: usize,
    /// Simulated seconds per program.
    #[arg(long, default_value_t = 60.0)]
    seconds: f64,
    /// The Python with player3 (scripts/setup.sh's).
    #[arg(long, default_value = ".venv/bin/python")]
    python: PathBuf,
    /// Programs at once in the second pass (by default one per core).
    #[arg(long)]
    jobs: Option<usize>,
}

/// A student's program: forward, turning away from what the laser sees ahead; each student's
/// turn differs a little, so that the class is not thirty copies of one run.
fn program(student: usize) -> String {
    let turn = 0.5 + 0.05 * (student % 10) as f64;
    format!(
        "import player3\n\
         robot = player3.connect()\n\
         base, laser = robot.position2d(0), robot.laser(0)\n\
         while True:\n\
         \x20   ahead = laser.read(timeout=30.0).ranges[60:120].min()\n\
         \x20   base.set_velocity(0.0, {turn}) if ahead < 0.8 else base.set_velocity(0.4, 0.0)\n"
    )
}

fn spec(world: &Path, seconds: f64) -> String {
    format!(
        "world = {world:?}\nrobot = \"r0\"\ntime_limit = {seconds}\nseed = 1\n\n\
         [[check]]\nname = \"travels\"\nkind = \"distance\"\nmin = 5\npoints = 50\n\n\
         [[check]]\nname = \"never bumps\"\nkind = \"no_stall\"\npoints = 50\n",
        world = world.display().to_string()
    )
}

/// One pass: the wall time and the summary it wrote.
fn grade(class: &Path, jobs: usize, python: &Path, out: &Path) -> Result<(f64, String)> {
    let grader = std::env::current_exe()?
        .parent()
        .context("the bench's folder")?
        .join("player-grade");
    ensure!(
        grader.is_file(),
        "no {}: cargo build --release -p player-grade",
        grader.display()
    );
    let mut submissions: Vec<PathBuf> = std::fs::read_dir(class.join("submissions"))?
        .map(|e| e.map(|e| e.path()))
        .collect::<Result<_, _>>()?;
    submissions.sort();
    let started = Instant::now();
    let done = Command::new(&grader)
        .arg(class.join("spec.toml"))
        .args(&submissions)
        .arg("--python")
        .arg(python)
        .arg("--out")
        .arg(out)
        .args(["--jobs", &jobs.to_string()])
        .output()?;
    let wall = started.elapsed().as_secs_f64();
    ensure!(
        done.status.success(),
        "{}",
        String::from_utf8_lossy(&done.stderr)
    );
    let summary = std::fs::read_to_string(out.join("summary.csv"))?;
    ensure!(
        !summary.contains("was not run") && !summary.contains("wall-clock cap"),
        "every program ran to its time limit:\n{summary}"
    );
    Ok((wall, summary))
}

fn main() -> Result<()> {
    let cli = Cli::parse();
    let python = std::path::absolute(&cli.python)?;
    ensure!(
        python.exists(),
        "no {}: run scripts/setup.sh",
        python.display()
    );
    let world = std::path::absolute("stage-worlds/simple.world")?;
    let scratch = std::env::temp_dir().join(format!("grade_class-{}", std::process::id()));
    let class = scratch.join("class");
    std::fs::create_dir_all(class.join("submissions"))?;
    std::fs::write(class.join("spec.toml"), spec(&world, cli.seconds))?;
    for student in 0..cli.submissions {
        std::fs::write(
            class
                .join("submissions")
                .join(format!("student{student:02}.py")),
            program(student),
        )?;
    }
    let jobs = cli
        .jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let real_time = cli.submissions as f64 * cli.seconds;
    println!(
        "{} programs x {} s simulated on {} core(s); one by one in real time: {real_time:.0} s",
        cli.submissions,
        cli.seconds,
        std::thread::available_parallelism().map_or(1, |n| n.get())
    );
    let (alone, first) = grade(&class, 1, &python, &scratch.join("alone"))?;
    println!(
        "  one at a time:  {alone:7.1} s wall  ({:.1}x faster than real time)",
        real_time / alone
    );
    let (together, second) = grade(&class, jobs, &python, &scratch.join("together"))?;
    println!(
        "  {jobs} at a time:   {together:7.1} s wall  ({:.1}x faster than real time, {:.2}x one at a time)",
        real_time / together,
        alone / together
    );
    ensure!(
        first == second,
        "the passes graded alike:\n{first}\n{second}"
    );
    println!("  both passes gave the same grades, word for word");
    std::fs::remove_dir_all(&scratch)?;
    Ok(())
}

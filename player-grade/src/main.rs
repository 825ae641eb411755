//! `player-grade SPEC.toml SUBMISSION... [--out DIR]`: grades each student's program.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::Parser;
use player_grade::class::{distinct_names, grade_class, write_class_files};
use player_grade::run::{Runner, Submission};
use player_grade::spec::Spec;

/// Grade robot programs: each runs against its own lockstep simulation of the spec's world
/// and is scored by the spec's checks.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Cli {
    /// The teacher's spec (TOML): world, robot, limits, checks. See docs/GRADING.md.
    spec: PathBuf,

    /// Students' programs: Python files, or folders with a main.py.
    #[arg(required = true)]
    submissions: Vec<PathBuf>,

    /// Where the results go: DIR/<name>/ per submission, and the class's summary.csv,
    /// junit.xml and report.html.
    #[arg(long, default_value = "grades")]
    out: PathBuf,

    /// The Python that runs the programs (it must have player3); by default python3 on PATH.
    #[arg(long, default_value = "python3")]
    python: PathBuf,

    /// Programs run at once (by default one per core).
    #[arg(long)]
    jobs: Option<usize>,
}

fn main() -> ExitCode {
    program_edge::logging::init("warn");
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("player-grade: {e:#}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: Cli) -> Result<()> {
    let spec = Spec::load(&cli.spec)?;
    let mut submissions = cli
        .submissions
        .iter()
        .map(|p| Submission::at(p))
        .collect::<Result<Vec<_>, _>>()?;
    distinct_names(&mut submissions);
    let python = which(&cli.python)
        .with_context(|| format!("no Python {} on PATH (give --python)", cli.python.display()))?;
    std::fs::create_dir_all(&cli.out).with_context(|| format!("making {}", cli.out.display()))?;
    let workers = cli.jobs.unwrap_or_else(|| {
        std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
    });
    eprintln!(
        "player-grade: {} submission(s) against {} ({} s simulated, {} at a time)",
        submissions.len(),
        spec.world.display(),
        spec.time_limit,
        workers
    );
    let runner = Runner::new(&python);
    let class = grade_class(&spec, &submissions, &runner, &cli.out, workers, &|g| {
        eprintln!(
            "player-grade: {:>20}  {:>6.1} / {}  {}",
            g.name, g.score, g.max_score, g.ended
        );
    });
    write_class_files(&spec, &class, &cli.out)?;
    eprintln!(
        "player-grade: report in {}",
        cli.out.join("report.html").display()
    );
    Ok(())
}

/// `program` as a path: itself when it names a file, else the first on PATH.
fn which(program: &std::path::Path) -> Option<PathBuf> {
    if program.components().count() > 1 {
        // Absolute, but not resolved: a virtual environment's python is a link that must stay
        // one, or the environment is lost.
        return std::path::absolute(program).ok().filter(|p| p.is_file());
    }
    std::env::var_os("PATH")
        .map(|paths| std::env::split_paths(&paths).collect::<Vec<_>>())
        .unwrap_or_default()
        .into_iter()
        .map(|dir| dir.join(program))
        .find(|p| p.is_file())
}

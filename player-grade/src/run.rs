//! One run: a student's program against its own simulation of the spec's world, in lockstep,
//! in its own sandbox, recorded; it ends at the time limit (simulated), when the program ends,
//! or at the wall-clock cap, and the program and all it started are killed.

use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use player_proto::recording::{RecorderError, RecorderStats};
use player_sim::serve::{LockstepOptions, Running, ServeOptions, serve};
use player_sim::served::{Source, devices_beside};
use player_sim::sim::Simulation;
use player_sim::sim_record::SimRecording;
use player_sim::world::World;

use crate::output::Output;
use crate::sandbox::{Privilege, Sandbox};
use crate::spec::Spec;
use crate::trace::Trace;

/// How often the run looks at its program and its simulation.
const LOOK: Duration = Duration::from_millis(10);
/// How long a run waits, once its program ended, for the program's last commands to be taken
/// (its connection closed, its last step stepped): the run then ends at the same step every
/// time.
const SETTLE: Duration = Duration::from_secs(3);

/// A student's submission.
#[derive(Debug, Clone)]
pub struct Submission {
    /// Its name in the reports (the file's or folder's name).
    pub name: String,
    /// The folder copied for the program to run in.
    pub folder: Option<PathBuf>,
    /// The Python file run.
    pub main: PathBuf,
}

/// Why a path is not a submission.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SubmissionError {
    #[error("{0}: a folder submission needs main.py")]
    NoMain(String),
    #[error("{0}: no such file or folder")]
    Missing(String),
}

impl Submission {
    /// A Python file, or a folder with `main.py`.
    pub fn at(path: &Path) -> Result<Submission, SubmissionError> {
        let name = path
            .file_stem()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(|| path.display().to_string());
        if path.is_dir() {
            let main = path.join("main.py");
            if !main.is_file() {
                return Err(SubmissionError::NoMain(path.display().to_string()));
            }
            Ok(Submission {
                name,
                folder: Some(path.to_path_buf()),
                main,
            })
        } else if path.is_file() {
            Ok(Submission {
                name,
                folder: None,
                main: path.to_path_buf(),
            })
        } else {
            Err(SubmissionError::Missing(path.display().to_string()))
        }
    }
}

/// Why a run ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Ending {
    /// The simulated time limit came.
    TimeLimit,
    /// The program ended by itself (its exit code, or the signal that ended it).
    Exited {
        code: Option<i32>,
        signal: Option<i32>,
    },
    /// The wall-clock cap came first.
    WallLimit,
    /// The program could not be started.
    NotStarted(String),
}

/// What one run gives.
#[derive(Debug, Clone)]
pub struct Outcome {
    pub trace: Trace,
    pub ending: Ending,
    pub output: Output,
    pub wall: Duration,
    /// Whether the program ever commanded a device.
    pub commanded: bool,
    /// Shared, so that an outcome can be cloned with its error.
    pub recording: Result<RecorderStats, std::sync::Arc<RecorderError>>,
    /// Said about the sandbox, when it is weaker than asked.
    pub sandbox_note: Option<String>,
}

/// Why a run could not be made at all (the grader's problem, not the program's).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RunError {
    #[error("{world}: {message}")]
    World { world: String, message: String },
    #[error("preparing {what}: {source}")]
    Io {
        what: String,
        source: std::io::Error,
    },
    #[error("recording to {path}: {message}")]
    Record { path: String, message: String },
}

fn io(what: impl Into<String>) -> impl FnOnce(std::io::Error) -> RunError {
    let what = what.into();
    move |source| RunError::Io { what, source }
}

/// The Python that runs the programs, and who it runs them as.
#[derive(Debug, Clone)]
pub struct Runner {
    pub python: PathBuf,
    pub privilege: Privilege,
}

impl Runner {
    /// Programs run by `python`, as `nobody` when it can run it.
    pub fn new(python: &Path) -> Runner {
        Runner {
            python: python.to_path_buf(),
            privilege: Privilege::for_python(python),
        }
    }
}

/// Runs `submission` under `spec`, writing `run.mcap` into `out`. Runs on the calling thread,
/// which it moves into the run's network namespace: call it on a thread of its own.
pub fn run(
    spec: &Spec,
    submission: &Submission,
    runner: &Runner,
    out: &Path,
) -> Result<Outcome, RunError> {
    let python = runner.python.as_path();
    let world_error = |message: String| RunError::World {
        world: spec.world.display().to_string(),
        message,
    };
    let work = prepare_folder(submission)?;
    let sandbox = Sandbox::enter(runner.privilege);
    let world = World::load(&spec.world).map_err(|e| world_error(e.to_string()))?;
    let robot = world
        .robots
        .iter()
        .position(|r| r.name == spec.robot)
        .ok_or_else(|| world_error(format!("no robot {:?}", spec.robot)))?;
    let devices = devices_beside(&spec.world, &world, &mut Vec::new())
        .map_err(|e| world_error(e.to_string()))?;
    let configured = devices
        .iter()
        .find(|d| {
            matches!(d.source, Source::Position { robot: r } if r == robot)
                && d.driver != "passthrough"
        })
        .map(|d| d.port)
        .ok_or_else(|| world_error(format!("{} has no position2d served", spec.robot)))?;
    let interval = world.interval;
    let mut sim = Simulation::new(world);
    sim.noise.seed = spec.seed;
    let (trace, observer) = Trace::observe(&sim, robot);
    let record_path = out.join("run.mcap");
    let recorder =
        player_mcap::reproducible_recorder(&record_path).map_err(|e| RunError::Record {
            path: record_path.display().to_string(),
            message: e.to_string(),
        })?;
    let options = ServeOptions {
        speedup: if spec.lockstep { 0.0 } else { 1.0 },
        free_ports: true,
        max_steps: Some((spec.time_limit / interval).round() as u64),
        lockstep: spec.lockstep.then_some(LockstepOptions {
            patience: Some(spec.patience),
        }),
        record: Some(SimRecording::to(&recorder)),
        observer: Some(observer),
        ..ServeOptions::default()
    };
    let mut running =
        serve(sim, devices, options).map_err(|e| world_error(format!("cannot serve: {e}")))?;
    let port = running.port(configured).unwrap_or(configured);
    let started = Instant::now();
    let (ending, output) = drive(
        &sandbox,
        &mut running,
        spec,
        submission,
        python,
        &work,
        port,
    );
    let wall = started.elapsed();
    let commanded = running.lockstep.as_ref().is_some_and(|l| l.ever_driven());
    running.stop();
    drop(running);
    let recording = recorder.finish().map_err(std::sync::Arc::new);
    let _ = std::fs::remove_dir_all(&work);
    let trace = trace.lock().unwrap_or_else(|e| e.into_inner()).clone();
    Ok(Outcome {
        trace,
        ending,
        output,
        wall,
        commanded,
        recording,
        sandbox_note: sandbox
            .not_isolated
            .clone()
            .or_else(|| runner.privilege.note(python)),
    })
}

/// Starts the program and waits for the run's end; kills whatever the program started.
fn drive(
    sandbox: &Sandbox,
    running: &mut Running,
    spec: &Spec,
    submission: &Submission,
    python: &Path,
    work: &Path,
    port: u16,
) -> (Ending, Output) {
    let main = work.join(submission.main.file_name().unwrap_or_default());
    let (reader, writer) = match std::io::pipe() {
        Ok(pipe) => pipe,
        Err(e) => {
            return (
                Ending::NotStarted(format!("no pipe: {e}")),
                Output::default(),
            );
        }
    };
    let output = Output::drain(reader);
    // Unique to this run: the namespace names it, else the program's folder does.
    let mark = format!("{}-{}", sandbox.mark(), work.display());
    let spawned = sandbox.command(python, work).and_then(|mut command| {
        command
            .arg(&main)
            .env_clear()
            .env("PATH", std::env::var_os("PATH").unwrap_or_default())
            .env("HOME", work)
            .env("TMPDIR", work)
            .env("LANG", "C.UTF-8")
            .env("PYTHONUNBUFFERED", "1")
            .env("PYTHONDONTWRITEBYTECODE", "1")
            .env("PLAYER_HOST", "127.0.0.1")
            .env("PLAYER_PORT", port.to_string())
            .env(crate::sandbox::MARK, &mark)
            .stdin(Stdio::null())
            .stdout(writer.try_clone()?)
            .stderr(writer);
        command.spawn()
    });
    let mut child = match spawned {
        Ok(child) => child,
        Err(e) => {
            return (
                Ending::NotStarted(format!("cannot start {}: {e}", python.display())),
                output,
            );
        }
    };
    let deadline = Instant::now() + spec.wall_limit;
    let ending = loop {
        if let Ok(Some(status)) = child.try_wait() {
            use std::os::unix::process::ExitStatusExt;
            settle(running);
            break Ending::Exited {
                code: status.code(),
                signal: status.signal(),
            };
        }
        if running.finished() {
            break Ending::TimeLimit;
        }
        if Instant::now() >= deadline {
            break Ending::WallLimit;
        }
        std::thread::sleep(LOOK);
    };
    sandbox.kill_all(child.id(), &mark);
    let _ = child.kill();
    let _ = child.wait();
    (ending, output)
}

/// Waits, at most [`SETTLE`], until the simulation has taken every step the ended program
/// answered.
fn settle(running: &Running) {
    let Some(lockstep) = &running.lockstep else {
        return;
    };
    let until = Instant::now() + SETTLE;
    while !lockstep.settled() && !running.finished() && Instant::now() < until {
        std::thread::sleep(LOOK);
    }
}

/// A fresh folder (readable by all, so that `nobody` can run from it) with the submission in
/// it.
fn prepare_folder(submission: &Submission) -> Result<PathBuf, RunError> {
    use std::os::unix::fs::PermissionsExt;
    let work = tempfile_dir().map_err(io("the program's folder"))?;
    std::fs::set_permissions(&work, std::fs::Permissions::from_mode(0o755))
        .map_err(io("the program's folder"))?;
    match &submission.folder {
        Some(folder) => {
            copy_folder(folder, &work).map_err(io(format!("copying {}", folder.display())))?
        }
        None => {
            let name = submission.main.file_name().unwrap_or_default();
            std::fs::copy(&submission.main, work.join(name))
                .map_err(io(format!("copying {}", submission.main.display())))?;
        }
    }
    Ok(work)
}

fn tempfile_dir() -> std::io::Result<PathBuf> {
    static NEXT: Mutex<u64> = Mutex::new(0);
    let mut next = NEXT.lock().unwrap_or_else(|e| e.into_inner());
    loop {
        *next += 1;
        let path =
            std::env::temp_dir().join(format!("player-grade-{}-{}", std::process::id(), *next));
        match std::fs::create_dir(&path) {
            Ok(()) => return Ok(path),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
}

fn copy_folder(from: &Path, to: &Path) -> std::io::Result<()> {
    for entry in std::fs::read_dir(from)? {
        let entry = entry?;
        let kind = entry.file_type()?;
        let target = to.join(entry.file_name());
        if kind.is_dir() {
            std::fs::create_dir_all(&target)?;
            copy_folder(&entry.path(), &target)?;
        } else if kind.is_file() {
            std::fs::copy(entry.path(), target)?;
        }
    }
    Ok(())
}

//! One submission graded: run, judged by every check, and its folder written — `results.json`
//! (Gradescope's format), `run.mcap`, `run.json` (what Python checks read) and `path.png`.
//! Whatever the program does, this gives a grade; only the grader's own trouble (a full disk)
//! is an error, and even that is graded as nothing with the reason said.

use std::path::Path;
use std::time::Duration;

use player_sim::world::World;

use crate::checks::Rule;
use crate::graded::Graded;
use crate::output::SHOWN_LINES;
use crate::python_check;
use crate::report::results_json;
use crate::run::{Ending, Outcome, Runner, Submission, run};
use crate::spec::Spec;

/// Runs and grades `submission` into `out/<name>/` (its name as given).
pub fn grade(spec: &Spec, submission: &Submission, runner: &Runner, out: &Path) -> Graded {
    let python = runner.python.as_path();
    let folder = out.join(&submission.name);
    let mut graded = Graded {
        name: submission.name.clone(),
        score: 0.0,
        max_score: spec.max_score(),
        verdicts: Vec::new(),
        ended: String::new(),
        output: String::new(),
        error: None,
        notes: Vec::new(),
        wall: Duration::ZERO,
        simulated: 0.0,
        folder: folder.clone(),
    };
    if let Err(e) = std::fs::create_dir_all(&folder) {
        graded.ended = format!("was not run: cannot make {}: {e}", folder.display());
        return graded;
    }
    // The run moves its thread into a network namespace of its own: a thread for each run.
    let outcome = std::thread::scope(|scope| {
        std::thread::Builder::new()
            .name(format!("run {}", submission.name))
            .spawn_scoped(scope, || run(spec, submission, runner, &folder))
            .map_err(|e| e.to_string())
            .and_then(|t| {
                t.join()
                    .map_err(|_| "the run's thread panicked".to_string())
            })
    });
    match outcome {
        Ok(Ok(outcome)) => match &outcome.ending {
            Ending::NotStarted(why) => {
                not_run(
                    spec,
                    &mut graded,
                    format!("the program could not be started ({why})"),
                );
            }
            _ => judge(spec, &outcome, python, &mut graded),
        },
        Ok(Err(e)) => not_run(spec, &mut graded, e.to_string()),
        Err(e) => not_run(spec, &mut graded, e),
    }
    write(spec, &graded, &folder);
    graded
}

/// No run: every check gives nothing, and says why.
fn not_run(spec: &Spec, graded: &mut Graded, why: String) {
    graded.ended = format!("was not run: {why}");
    graded.verdicts = spec
        .checks
        .iter()
        .map(|c| c.verdict(0.0, "not run".into()))
        .collect();
}

fn judge(spec: &Spec, outcome: &Outcome, python: &Path, graded: &mut Graded) {
    let simulated = outcome.trace.duration();
    graded.simulated = simulated;
    graded.wall = outcome.wall;
    graded.output = outcome.output.last_lines(SHOWN_LINES);
    graded.ended = match &outcome.ending {
        Ending::TimeLimit => format!("ran to the time limit ({} s simulated)", spec.time_limit),
        Ending::Exited { code: Some(0), .. } => {
            format!("ended when the program did, at {simulated:.1} s simulated")
        }
        Ending::Exited {
            code: Some(code), ..
        } => {
            graded.error = outcome.output.python_error();
            format!(
                "ended when the program failed (exit status {code}), at {simulated:.1} s simulated"
            )
        }
        Ending::Exited { signal, .. } => format!(
            "ended when the program was killed (signal {}), at {simulated:.1} s simulated",
            signal.unwrap_or(0)
        ),
        Ending::WallLimit => format!(
            "was stopped at the wall-clock cap ({} s), at {simulated:.1} s simulated",
            spec.wall_limit.as_secs_f64()
        ),
        Ending::NotStarted(why) => format!("was not run: the program could not be started: {why}"),
    };
    if spec.lockstep && !outcome.commanded {
        graded
            .notes
            .push("the program never commanded the robot".into());
    }
    if let Some(note) = &outcome.sandbox_note {
        graded.notes.push(note.clone());
    }
    match &outcome.recording {
        Ok(stats) if stats.lost() > 0 => graded
            .notes
            .push(format!("the recording lost {} records", stats.lost())),
        Ok(_) => {}
        Err(e) => graded.notes.push(format!("the recording failed: {e}")),
    }
    let run_file = graded.folder.join("run.json");
    let run = python_check::run_json(&outcome.trace, &graded.ended, &graded.output);
    if let Err(e) = std::fs::write(&run_file, run.to_string()) {
        graded
            .notes
            .push(format!("cannot write {}: {e}", run_file.display()));
    }
    for check in &spec.checks {
        let verdict = match &check.rule {
            Rule::Python { file, function } => {
                match python_check::judge(python, file, function, &run_file) {
                    Ok((share, message)) => check.verdict(share, message),
                    Err(e) => check.verdict(0.0, e.to_string()),
                }
            }
            _ => check
                .judge(&outcome.trace)
                .unwrap_or_else(|| check.verdict(0.0, String::new())),
        };
        graded.verdicts.push(verdict);
    }
    graded.score = graded.verdicts.iter().map(|v| v.score).sum();
    if let Ok(world) = World::load(&spec.world) {
        let picture = crate::picture::draw(&world, &outcome.trace, &spec.checks, &graded.verdicts);
        let path = graded.folder.join("path.png");
        if let Err(e) = picture.save(&path) {
            graded
                .notes
                .push(format!("cannot write {}: {e}", path.display()));
        }
    }
}

fn write(spec: &Spec, graded: &Graded, folder: &Path) {
    let results = results_json(spec, graded);
    let path = folder.join("results.json");
    let text = serde_json::to_string_pretty(&results).unwrap_or_default();
    if let Err(e) = std::fs::write(&path, text) {
        tracing::error!("cannot write {}: {e}", path.display());
    }
}

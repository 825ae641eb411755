//! A class graded: every submission run and graded, as many at once as there are cores (each
//! run is lockstep, so sharing the machine changes no grade), then the class's summary files.

use std::path::Path;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use crate::grade::grade;
use crate::graded::Graded;
use crate::report::{junit_xml, report_html, summary_csv};
use crate::run::{Runner, Submission};
use crate::spec::Spec;

/// Why the class's files could not be written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ClassError {
    #[error("cannot write {path}: {source}")]
    Write {
        path: String,
        source: std::io::Error,
    },
}

/// Gives submissions that share a name (`alice.py` and `alice/`) names of their own.
pub fn distinct_names(submissions: &mut [Submission]) {
    let mut seen: Vec<String> = Vec::new();
    for submission in submissions.iter_mut() {
        let mut name = submission.name.clone();
        let mut n = 2;
        while seen.contains(&name) {
            name = format!("{}-{n}", submission.name);
            n += 1;
        }
        seen.push(name.clone());
        submission.name = name;
    }
}

/// Grades every submission with `workers` at a time, in `out`; the grades in the order given.
/// `done` is told of each grade as it comes.
pub fn grade_class(
    spec: &Spec,
    submissions: &[Submission],
    runner: &Runner,
    out: &Path,
    workers: usize,
    done: &(dyn Fn(&Graded) + Sync),
) -> Vec<Graded> {
    let next = AtomicUsize::new(0);
    let grades: Mutex<Vec<Option<Graded>>> = Mutex::new(vec![None; submissions.len()]);
    std::thread::scope(|scope| {
        for _ in 0..workers.clamp(1, submissions.len().max(1)) {
            scope.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(submission) = submissions.get(i) else {
                        break;
                    };
                    let graded = grade(spec, submission, runner, out);
                    done(&graded);
                    grades.lock().unwrap_or_else(|e| e.into_inner())[i] = Some(graded);
                }
            });
        }
    });
    grades
        .into_inner()
        .unwrap_or_else(|e| e.into_inner())
        .into_iter()
        .flatten()
        .collect()
}

/// `summary.csv`, `junit.xml` and `report.html` in `out`.
pub fn write_class_files(spec: &Spec, class: &[Graded], out: &Path) -> Result<(), ClassError> {
    let files = [
        ("summary.csv", summary_csv(spec, class)),
        ("junit.xml", junit_xml(spec, class)),
        ("report.html", report_html(spec, class, out)),
    ];
    for (name, text) in files {
        let path = out.join(name);
        std::fs::write(&path, text).map_err(|source| ClassError::Write {
            path: path.display().to_string(),
            source,
        })?;
    }
    Ok(())
}

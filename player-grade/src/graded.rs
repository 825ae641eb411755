//! What grading a submission found: its score, each check's verdict, how its run ended and
//! what it printed, as the reports and the class files read it.

use std::path::PathBuf;
use std::time::Duration;

use crate::checks::Verdict;

/// A submission's grade.
#[derive(Debug, Clone)]
pub struct Graded {
    pub name: String,
    pub score: f64,
    pub max_score: f64,
    pub verdicts: Vec<Verdict>,
    /// How the run ended, in a sentence.
    pub ended: String,
    /// The program's last lines.
    pub output: String,
    /// The program's error, when it failed.
    pub error: Option<String>,
    /// What else a teacher should know (never commanded, not isolated, recording trouble).
    pub notes: Vec<String>,
    /// Wall-clock seconds the run took.
    pub wall: Duration,
    /// Simulated seconds the run lasted.
    pub simulated: f64,
    /// `DIR/<name>`.
    pub folder: PathBuf,
}

//! Timed scripts for `pv3d --script FILE`: one `<seconds> <sentence>` a line, seconds counted
//! from when the viewer starts running; `#` starts a comment. Lines run in the order of their
//! times (a later line with the same time runs after an earlier one).

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The longest wait a script line may ask for: a day.
const LONGEST_WAIT_S: f64 = 86_400.0;

/// A script that cannot be read, naming file:line.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ScriptError {
    #[error("{}: cannot read: {message}", path.display())]
    Io { path: PathBuf, message: String },
    #[error("{}:{line}: {message}", path.display())]
    At {
        path: PathBuf,
        line: usize,
        message: String,
    },
}

/// One sentence and when to say it.
#[derive(Debug, Clone, PartialEq)]
pub struct ScriptLine {
    pub at: Duration,
    pub sentence: String,
    /// 1-based line in the file, for messages.
    pub line: usize,
}

/// A loaded script, and how far it has been run.
#[derive(Debug, Clone, PartialEq)]
pub struct Script {
    pub path: PathBuf,
    pub lines: Vec<ScriptLine>,
    started: Option<Instant>,
    next: usize,
}

impl Script {
    pub fn load(path: &Path) -> Result<Script, ScriptError> {
        let text = std::fs::read_to_string(path).map_err(|e| ScriptError::Io {
            path: path.to_path_buf(),
            message: e.to_string(),
        })?;
        Script::from_str(&text, path)
    }

    /// Reads script text; `path` names it in messages.
    pub fn from_str(text: &str, path: &Path) -> Result<Script, ScriptError> {
        let mut lines = Vec::new();
        for (index, raw) in text.lines().enumerate() {
            let line = index + 1;
            let content = raw.split('#').next().unwrap_or("").trim();
            if content.is_empty() {
                continue;
            }
            let error = |message: String| ScriptError::At {
                path: path.to_path_buf(),
                line,
                message,
            };
            let (seconds, sentence) = content.split_once(char::is_whitespace).ok_or_else(|| {
                error(format!(
                    "expected <seconds> <sentence>, e.g. \"2.5 robot1 go to dock\"; found {content:?}"
                ))
            })?;
            let seconds: f64 = seconds
                .parse()
                .map_err(|_| error(format!("{seconds:?} is not a number of seconds")))?;
            if !(0.0..=LONGEST_WAIT_S).contains(&seconds) {
                return Err(error(format!(
                    "seconds must be from 0 to {LONGEST_WAIT_S}, not {seconds}"
                )));
            }
            lines.push(ScriptLine {
                at: Duration::from_secs_f64(seconds),
                sentence: sentence.trim().to_string(),
                line,
            });
        }
        lines.sort_by_key(|l| l.at);
        Ok(Script {
            path: path.to_path_buf(),
            lines,
            started: None,
            next: 0,
        })
    }

    /// The lines due by `now`, each once; the first call starts the clock.
    pub fn due(&mut self, now: Instant) -> Vec<ScriptLine> {
        let started = *self.started.get_or_insert(now);
        let elapsed = now.saturating_duration_since(started);
        let first = self.next;
        while self.next < self.lines.len() && self.lines[self.next].at <= elapsed {
            self.next += 1;
        }
        self.lines[first..self.next].to_vec()
    }

    /// Whether every line has run.
    pub fn finished(&self) -> bool {
        self.next == self.lines.len()
    }

    /// Where a line is, for messages: `file:line`.
    pub fn place(&self, line: &ScriptLine) -> String {
        format!("{}:{}", self.path.display(), line.line)
    }
}

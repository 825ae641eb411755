//! Speech in and out for tests without microphones or speakers: a `speech_recognition` device
//! that "hears" sentences read from a file (each at a simulated time) or from standard input,
//! and a `speech` device that logs what it is told to say and, when `espeak-ng` is installed,
//! speaks it into WAV files.

use std::collections::VecDeque;
use std::io::{BufRead, Write};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use crate::worldfile::WorldFileError;

/// The program that turns text into speech, when installed.
const SPEAKER: &str = "espeak-ng";

/// Sentences waiting to be heard, each with the simulated time it is heard at.
#[derive(Debug, Clone, Default)]
pub struct SpeechInput(Arc<Mutex<VecDeque<(f64, String)>>>);

impl PartialEq for SpeechInput {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl Eq for SpeechInput {}

impl SpeechInput {
    /// Sentences from a file: `<seconds> <sentence>` a line (simulated seconds), `#` comments.
    pub fn from_file(path: &Path) -> Result<SpeechInput, WorldFileError> {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path)
            .map_err(|e| WorldFileError::at(&name, 1, 1, format!("cannot read: {e}")))?;
        SpeechInput::from_text(&text, &name)
    }

    /// Reads sentence text; `name` names it in errors (file:line:col).
    pub fn from_text(text: &str, name: &str) -> Result<SpeechInput, WorldFileError> {
        let mut sentences = Vec::new();
        for (index, raw) in text.lines().enumerate() {
            let content = raw.split('#').next().unwrap_or("").trim();
            if content.is_empty() {
                continue;
            }
            let col = raw.len() - raw.trim_start().len() + 1;
            let bad = |message: String| WorldFileError::at(name, index + 1, col, message);
            let (seconds, sentence) = content
                .split_once(char::is_whitespace)
                .ok_or_else(|| bad(format!("expected <seconds> <sentence>, found {content:?}")))?;
            let at: f64 = seconds
                .parse()
                .ok()
                .filter(|s: &f64| s.is_finite() && *s >= 0.0)
                .ok_or_else(|| bad(format!("{seconds:?} is not a number of seconds")))?;
            sentences.push((at, sentence.trim().to_string()));
        }
        sentences.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(SpeechInput(Arc::new(Mutex::new(sentences.into()))))
    }

    /// Sentences typed on standard input, each heard as soon as its line is read.
    pub fn from_stdin() -> SpeechInput {
        let input = SpeechInput::default();
        let queue = input.0.clone();
        let reader = std::thread::Builder::new()
            .name("player-sim speech input".into())
            .spawn(move || {
                for line in std::io::stdin().lock().lines() {
                    let Ok(line) = line else { break };
                    if !line.trim().is_empty() {
                        queue.lock().expect("speech queue").push_back((0.0, line));
                    }
                }
            });
        if let Err(e) = reader {
            tracing::error!("cannot read speech from standard input: {e}");
        }
        input
    }

    /// The sentences heard by simulated time `now`, each once.
    pub fn heard(&self, now: f64) -> Vec<String> {
        let mut queue = self.0.lock().expect("speech queue");
        let mut heard = Vec::new();
        while queue.front().is_some_and(|(at, _)| *at <= now) {
            heard.extend(queue.pop_front().map(|(_, s)| s));
        }
        heard
    }
}

/// Where a `speech` device puts what it says.
#[derive(Debug, Clone, Default)]
pub struct SpeechOutput {
    /// A text file every sentence is appended to, a line each.
    pub log: Option<PathBuf>,
    /// `said` → `said-1.wav`, `said-2.wav`, … spoken by espeak-ng when installed.
    pub wav: Option<PathBuf>,
    said: Arc<Mutex<Vec<String>>>,
}

impl PartialEq for SpeechOutput {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.said, &other.said)
    }
}

impl Eq for SpeechOutput {}

impl SpeechOutput {
    pub fn new(log: Option<PathBuf>, wav: Option<PathBuf>) -> SpeechOutput {
        SpeechOutput {
            log,
            wav,
            said: Arc::default(),
        }
    }

    /// Everything said so far.
    pub fn said(&self) -> Vec<String> {
        self.said.lock().expect("speech log").clone()
    }

    /// Says `text`: logs it, appends it to the log file, and speaks it into a WAV file.
    pub fn say(&self, text: &str) {
        tracing::info!("speech: {text}");
        let count = {
            let mut said = self.said.lock().expect("speech log");
            said.push(text.to_string());
            said.len()
        };
        if let Some(log) = &self.log {
            let written = std::fs::OpenOptions::new()
                .create(true)
                .append(true)
                .open(log)
                .and_then(|mut f| writeln!(f, "{text}"));
            if let Err(e) = written {
                tracing::error!("speech: cannot write {}: {e}", log.display());
            }
        }
        if let Some(prefix) = &self.wav {
            let mut name = prefix.as_os_str().to_os_string();
            name.push(format!("-{count}.wav"));
            speak_into(PathBuf::from(name), text.to_string());
        }
    }
}

/// Runs espeak-ng in the background (it takes a moment; the server must not wait for it).
fn speak_into(wav: PathBuf, text: String) {
    let spoken = std::thread::Builder::new()
        .name("player-sim speech".into())
        .spawn(move || {
            match std::process::Command::new(SPEAKER)
                .arg("-w")
                .arg(&wav)
                .arg(&text)
                .status()
            {
                Ok(status) if status.success() => {
                    tracing::debug!("speech: spoke into {}", wav.display());
                }
                Ok(status) => tracing::warn!("speech: {SPEAKER} failed ({status})"),
                Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                    tracing::debug!("speech: {SPEAKER} is not installed; logged only");
                }
                Err(e) => tracing::warn!("speech: cannot run {SPEAKER}: {e}"),
            }
        });
    if let Err(e) = spoken {
        tracing::warn!("speech: {e}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sentences_are_heard_in_time_order_each_once() {
        let input =
            SpeechInput::from_text("2 r0 stop\n# note\n\n0.5 r0 go to dock\n", "s").unwrap();
        assert!(input.heard(0.4).is_empty());
        assert_eq!(input.heard(1.0), vec!["r0 go to dock"]);
        assert_eq!(input.heard(5.0), vec!["r0 stop"]);
        assert!(input.heard(9.0).is_empty());
    }

    #[test]
    fn a_bad_line_is_named_by_file_line_and_column() {
        let e = SpeechInput::from_text("1 ok\n  soon r0 stop\n", "said.txt").unwrap_err();
        assert_eq!(
            e.to_string(),
            "said.txt:2:3: \"soon\" is not a number of seconds"
        );
        let e = SpeechInput::from_text("3\n", "said.txt").unwrap_err();
        assert!(e.to_string().starts_with("said.txt:1:1: expected"), "{e}");
    }

    #[test]
    fn what_is_said_is_kept_and_logged_to_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let log = dir.path().join("said.txt");
        let out = SpeechOutput::new(Some(log.clone()), None);
        out.say("hello");
        out.say("r0: stopping");
        assert_eq!(out.said(), vec!["hello", "r0: stopping"]);
        assert_eq!(
            std::fs::read_to_string(log).unwrap(),
            "hello\nr0: stopping\n"
        );
    }
}

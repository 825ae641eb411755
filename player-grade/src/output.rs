//! A program's output, kept bounded: everything it prints is read (so it never blocks on a
//! full pipe), but only the last bytes are kept, and the count of the rest.

use std::collections::VecDeque;
use std::io::Read;
use std::sync::{Arc, Condvar, Mutex};
use std::time::Duration;

/// Bytes of output kept: the end of it.
const KEPT: usize = 32 * 1024;
/// Lines of output a result shows.
pub const SHOWN_LINES: usize = 30;

#[derive(Debug, Default)]
struct Kept {
    tail: VecDeque<u8>,
    total: u64,
    /// The pipe reached its end: every writer is gone and all was read.
    closed: bool,
}

/// The end of what a program printed, filled by a thread reading its pipe.
#[derive(Debug, Clone, Default)]
pub struct Output(Arc<(Mutex<Kept>, Condvar)>);

impl Output {
    /// Reads `from` to its end on a thread of its own.
    pub fn drain(from: impl Read + Send + 'static) -> Output {
        let output = Output::default();
        let kept = output.0.clone();
        let _ = std::thread::Builder::new()
            .name("player-grade output".into())
            .spawn(move || {
                let mut from = from;
                let mut buffer = [0u8; 8192];
                while let Ok(n) = from.read(&mut buffer) {
                    if n == 0 {
                        break;
                    }
                    let mut kept = kept.0.lock().unwrap_or_else(|e| e.into_inner());
                    kept.total += n as u64;
                    kept.tail.extend(&buffer[..n]);
                    let excess = kept.tail.len().saturating_sub(KEPT);
                    kept.tail.drain(..excess);
                }
                kept.0.lock().unwrap_or_else(|e| e.into_inner()).closed = true;
                kept.1.notify_all();
            });
        output
    }

    fn kept(&self) -> std::sync::MutexGuard<'_, Kept> {
        self.0.0.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Waits, at most `limit`, until the pipe is read to its end; whether it was.
    pub fn wait_closed(&self, limit: Duration) -> bool {
        let kept = self.kept();
        let (kept, _) = self
            .0
            .1
            .wait_timeout_while(kept, limit, |k| !k.closed)
            .unwrap_or_else(|e| e.into_inner());
        kept.closed
    }

    /// Bytes printed in all.
    pub fn total(&self) -> u64 {
        self.kept().total
    }

    /// The last `lines` lines, with a first line saying what was left out.
    pub fn last_lines(&self, lines: usize) -> String {
        let kept = self.kept();
        let bytes: Vec<u8> = kept.tail.iter().copied().collect();
        let text = String::from_utf8_lossy(&bytes);
        let all: Vec<&str> = text.lines().collect();
        let from = all.len().saturating_sub(lines);
        let mut out = String::new();
        let shown: usize = all[from..].iter().map(|l| l.len() + 1).sum();
        if (shown as u64) < kept.total {
            out.push_str(&format!(
                "[{} bytes printed; the last {} lines:]\n",
                kept.total,
                all.len() - from
            ));
        }
        for line in &all[from..] {
            out.push_str(line);
            out.push('\n');
        }
        out
    }

    /// The error a Python program died of: its traceback's last line.
    pub fn python_error(&self) -> Option<String> {
        let text = self.last_lines(SHOWN_LINES);
        let lines: Vec<&str> = text.lines().collect();
        let traceback = lines.iter().rposition(|l| l.starts_with("Traceback"))?;
        lines[traceback..]
            .iter()
            .rev()
            .find(|l| !l.starts_with(' ') && !l.is_empty())
            .map(|l| l.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read_all(text: Vec<u8>) -> Output {
        let output = Output::drain(std::io::Cursor::new(text));
        assert!(
            output.wait_closed(Duration::from_secs(10)),
            "read to its end"
        );
        output
    }

    #[test]
    fn a_flood_keeps_its_end_and_counts_the_rest() {
        let text: Vec<u8> = (0..100_000)
            .flat_map(|i| format!("line {i}\n").into_bytes())
            .collect();
        let total = text.len() as u64;
        let output = read_all(text);
        assert_eq!(output.total(), total);
        let shown = output.last_lines(3);
        assert_eq!(
            shown,
            format!(
                "[{total} bytes printed; the last 3 lines:]\nline 99997\nline 99998\nline 99999\n"
            )
        );
    }

    #[test]
    fn a_traceback_gives_its_error() {
        let output = read_all(
            b"hello\nTraceback (most recent call last):\n  File \"x.py\", line 1\nZeroDivisionError: division by zero\n"
                .to_vec(),
        );
        assert_eq!(
            output.python_error().as_deref(),
            Some("ZeroDivisionError: division by zero")
        );
    }
}

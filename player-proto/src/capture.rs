//! Reading recorded Player sessions: the JSON-lines format of the project's captures, one
//! `recv()` chunk per line, `{"t": 0.018, "dir": "s2c", "hex": "506c61…"}`.
//!
//! Chunk boundaries are arbitrary; concatenating one direction's bytes gives the stream
//! (server to client: the banner, then messages; client to server: messages only).

use std::fmt;
use std::fmt::Write as _;

pub mod trim;

/// Which way a chunk travelled.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    ServerToClient,
    ClientToServer,
}

impl fmt::Display for Direction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Direction::ServerToClient => "s2c",
            Direction::ClientToServer => "c2s",
        })
    }
}

/// One recorded chunk.
#[derive(Debug, Clone, PartialEq)]
pub struct Chunk {
    /// Seconds since the connection was accepted.
    pub t: f64,
    pub dir: Direction,
    pub bytes: Vec<u8>,
}

/// A line that is not a chunk.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("capture line {line}: {reason}")]
pub struct CaptureError {
    pub line: usize,
    pub reason: String,
}

/// The value after `"key":` on a line (a number, or a string without escapes).
fn field<'a>(line: &'a str, key: &str) -> Option<&'a str> {
    let start = line.find(&format!("\"{key}\""))? + key.len() + 2;
    let rest = line[start..].trim_start().strip_prefix(':')?.trim_start();
    if let Some(s) = rest.strip_prefix('"') {
        return s.find('"').map(|end| &s[..end]);
    }
    let end = rest.find([',', '}']).unwrap_or(rest.len());
    Some(rest[..end].trim())
}

fn hex_bytes(hex: &str) -> Option<Vec<u8>> {
    if !hex.len().is_multiple_of(2) {
        return None;
    }
    (0..hex.len())
        .step_by(2)
        .map(|i| u8::from_str_radix(hex.get(i..i + 2)?, 16).ok())
        .collect()
}

/// Parses a whole capture.
pub fn parse_capture(text: &str) -> Result<Vec<Chunk>, CaptureError> {
    let mut chunks = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let line_no = n + 1;
        if line.trim().is_empty() {
            continue;
        }
        let err = |reason: &str| CaptureError {
            line: line_no,
            reason: reason.to_string(),
        };
        let t = field(line, "t")
            .and_then(|t| t.parse().ok())
            .ok_or_else(|| err("no numeric \"t\""))?;
        let dir = match field(line, "dir") {
            Some("s2c") => Direction::ServerToClient,
            Some("c2s") => Direction::ClientToServer,
            _ => return Err(err("\"dir\" must be \"s2c\" or \"c2s\"")),
        };
        let bytes = field(line, "hex")
            .and_then(hex_bytes)
            .ok_or_else(|| err("\"hex\" is not an even-length hex string"))?;
        chunks.push(Chunk { t, dir, bytes });
    }
    Ok(chunks)
}

/// All bytes of one direction, in order.
pub fn stream(chunks: &[Chunk], dir: Direction) -> Vec<u8> {
    chunks
        .iter()
        .filter(|c| c.dir == dir)
        .flat_map(|c| c.bytes.iter().copied())
        .collect()
}

/// Writes chunks in the capture format, one line each; [`parse_capture`] reads them back.
///
/// Times keep the recordings' resolution (microseconds), so a capture that was read and written
/// again differs from its source only where the source itself was written differently.
pub fn write_capture(chunks: &[Chunk]) -> String {
    let mut out = String::new();
    for chunk in chunks {
        write!(
            out,
            "{{\"t\": {:.6}, \"dir\": \"{}\", \"hex\": \"",
            chunk.t, chunk.dir
        )
        .expect("writing to a String cannot fail");
        for byte in &chunk.bytes {
            write!(out, "{byte:02x}").expect("writing to a String cannot fail");
        }
        out.push_str("\"}\n");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_chunks_and_joins_a_direction() {
        let text = "{\"t\": 0.5, \"dir\": \"s2c\", \"hex\": \"0102\"}\n{\"t\": 1, \"dir\": \"c2s\", \"hex\": \"ff\"}\n{\"t\": 2, \"dir\": \"s2c\", \"hex\": \"03\"}\n";
        let chunks = parse_capture(text).unwrap();
        assert_eq!(chunks.len(), 3);
        assert_eq!(stream(&chunks, Direction::ServerToClient), [1, 2, 3]);
        assert_eq!(chunks[1].t, 1.0);
    }

    #[test]
    fn written_chunks_read_back_unchanged() {
        let text = concat!(
            "{\"t\": 0.008256, \"dir\": \"s2c\", \"hex\": \"506c61\"}\n",
            "{\"t\": 12.500000, \"dir\": \"c2s\", \"hex\": \"00ff\"}\n",
        );
        let chunks = parse_capture(text).unwrap();
        assert_eq!(write_capture(&chunks), text);
    }

    #[test]
    fn bad_lines_name_their_number() {
        let err = parse_capture("{\"t\": 0, \"dir\": \"s2c\", \"hex\": \"0\"}").unwrap_err();
        assert_eq!(err.line, 1);
        assert!(parse_capture("{\"t\": x}").is_err());
    }
}

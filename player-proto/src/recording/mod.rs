//! Recordings: every message of every connection of a client, losslessly, with its receive
//! time, in an append-only file that survives a crash (`docs/RECORDING-FORMAT.md`).
//!
//! * [`format`] — the file header, the record framing, the record kinds; [`record_error`] why
//!   a payload is not a record.
//! * [`writer`] / [`reader`] — appending records; reading them back without trusting the file.
//! * [`from_capture`] — a capture of real Player traffic (`captures/`) as records.
//! * [`index`] — one pass for what a replay or a summary needs (devices, replies, seeking).
//! * [`source`] — a recording read from its start or from a seek point, whatever file holds it.
//! * [`playerlog`] — export to the text format of Player's `writelog`/`readlog` drivers.
//! * [`recorder`] — a client tap that writes on its own thread and counts what it could not,
//!   into a `.prec` or any other [`sink::RecordSink`].
//!
//! ```no_run
//! use player_proto::client::{Client, ClientOptions};
//! use player_proto::recording::Recorder;
//! let recorder = Recorder::create("robot.prec".as_ref()).unwrap();
//! let options = ClientOptions { tap: Some(recorder.tap()), ..ClientOptions::default() };
//! let mut robot = Client::connect("localhost", 6665, options).unwrap();
//! robot.laser(0).subscribe().unwrap();
//! // … later
//! robot.close();
//! let stats = recorder.finish().unwrap();
//! assert_eq!(stats.lost(), 0);
//! ```

pub mod format;
pub mod from_capture;
pub mod index;
pub mod playerlog;
pub mod reader;
pub mod record_error;
pub mod recorder;
pub mod sink;
pub mod source;
pub mod writer;

pub use format::{Event, Record};
pub use index::RecordingIndex;
pub use reader::{ReadError, RecordingReader};
pub use record_error::RecordError;
pub use recorder::{ConnectionOpener, Recorder, RecorderError, RecorderStats};
pub use sink::RecordSink;
pub use source::{PrecFile, RecordSource, RecordStream, SourceError};
pub use writer::{RecordingWriter, WriteError};

/// The conventional file extension of a recording.
pub const EXTENSION: &str = "prec";

/// Opens a recording file for reading, buffered.
pub fn open(
    path: &std::path::Path,
) -> Result<RecordingReader<std::io::BufReader<std::fs::File>>, ReadError> {
    let file = std::fs::File::open(path).map_err(|source| ReadError::Io { offset: 0, source })?;
    RecordingReader::new(std::io::BufReader::new(file))
}

#[cfg(test)]
mod tests;

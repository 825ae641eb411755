//! Recording straight into an MCAP file: a [`RecordSink`] for `player_proto`'s recorder, and
//! [`recorder`], which picks the format by the file's name (`*.mcap`, else a `.prec`) for the
//! programs that record (`playerrecord record`, `pv3d --record`).
//!
//! An MCAP file is written a chunk at a time and indexed at its end. A chunk is ended (and so
//! is safe from a crash) when it is full or when the queue runs dry a second after the last
//! one ended: a crash loses at most about a second, as a `.prec` loses what was queued; a
//! file whose end was never written reads, record by record, up to its last whole chunk.

use std::fs::File;
use std::io::{self, BufWriter, Seek, SeekFrom, Write};
use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

use player_proto::recording::{Record, RecordSink, Recorder, RecorderError};

use crate::{EXTENSION, McapOptions, McapRecordWriter, McapWriteError};

/// How long the data may sit in an unfinished chunk while nothing else arrives.
const CHUNK_AT_MOST: Duration = Duration::from_secs(1);

/// Why a recording could not start.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RecordError {
    #[error("cannot create the recording {path}: {source}")]
    Create { path: String, source: io::Error },
    #[error("cannot start the MCAP recording {path}: {source}")]
    Mcap {
        path: String,
        source: McapWriteError,
    },
    #[error(transparent)]
    Recorder(#[from] RecorderError),
}

/// A recorder writing to `path`: MCAP when it is named `*.mcap`, else a `.prec`.
pub fn recorder(path: &Path) -> Result<Recorder, RecordError> {
    recorder_chunked(path, Some(CHUNK_AT_MOST))
}

/// A recorder for records on a clock of their own (a lockstep simulation's): an MCAP file's
/// chunks end only when full, not a second after the last, so that the same records make the
/// same bytes however fast they came.
pub fn reproducible_recorder(path: &Path) -> Result<Recorder, RecordError> {
    recorder_chunked(path, None)
}

/// A recorder whose MCAP chunks also end `chunk_at_most` after the last one, if given.
fn recorder_chunked(path: &Path, chunk_at_most: Option<Duration>) -> Result<Recorder, RecordError> {
    let mcap = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case(EXTENSION));
    if !mcap {
        return Ok(Recorder::create(path)?);
    }
    let name = || path.display().to_string();
    let file = File::create(path).map_err(|source| RecordError::Create {
        path: name(),
        source,
    })?;
    let length = Arc::new(AtomicU64::new(0));
    let out = Counted {
        inner: BufWriter::with_capacity(1 << 20, file),
        at: 0,
        end: length.clone(),
    };
    let writer =
        McapRecordWriter::new(out, McapOptions::default()).map_err(|source| RecordError::Mcap {
            path: name(),
            source,
        })?;
    Ok(Recorder::to_sink(McapSink {
        writer: Some(writer),
        chunk_started: Instant::now(),
        chunk_at_most,
        length,
    })?)
}

/// The recorder's MCAP destination.
pub struct McapSink {
    /// `None` once finished.
    writer: Option<McapRecordWriter<Counted<BufWriter<File>>>>,
    chunk_started: Instant,
    /// How long a chunk may stay open while nothing arrives (`None`: until it is full).
    chunk_at_most: Option<Duration>,
    /// The file's length so far, kept by its writer.
    length: Arc<AtomicU64>,
}

impl McapSink {
    fn writer(&mut self) -> &mut McapRecordWriter<Counted<BufWriter<File>>> {
        self.writer
            .as_mut()
            .expect("a sink written to after finishing")
    }
}

impl RecordSink for McapSink {
    type Error = McapWriteError;

    fn write(&mut self, record: &Record) -> Result<(), McapWriteError> {
        self.writer().write(record)
    }

    fn flush(&mut self) -> Result<(), McapWriteError> {
        if self
            .chunk_at_most
            .is_some_and(|most| self.chunk_started.elapsed() >= most)
        {
            self.chunk_started = Instant::now();
            self.writer().flush()?;
        }
        Ok(())
    }

    fn finish(&mut self) -> Result<(), McapWriteError> {
        match self.writer.take() {
            Some(writer) => {
                let records = writer.records();
                let mut out = writer.finish()?;
                out.flush().map_err(|e| McapWriteError::Mcap {
                    records,
                    source: e.into(),
                })
            }
            None => Ok(()),
        }
    }

    fn bytes(&self) -> u64 {
        self.length.load(Ordering::Relaxed)
    }
}

/// A writer that knows how long the file it writes is.
pub struct Counted<W> {
    inner: W,
    at: u64,
    end: Arc<AtomicU64>,
}

impl<W: Write> Write for Counted<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let n = self.inner.write(buf)?;
        self.at += n as u64;
        self.end.fetch_max(self.at, Ordering::Relaxed);
        Ok(n)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.inner.flush()
    }
}

impl<W: Seek> Seek for Counted<W> {
    fn seek(&mut self, to: SeekFrom) -> io::Result<u64> {
        self.at = self.inner.seek(to)?;
        Ok(self.at)
    }
}

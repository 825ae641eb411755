//! Where a recording's records are read from, whatever holds them: a `.prec` file here, an MCAP
//! file in `player_mcap`. A replay reads a source once through to index it ([`RecordingIndex`])
//! and then again from the seek points that pass noted, as often as it seeks; nothing is
//! converted into a temporary file first.
//!
//! [`RecordingIndex`]: super::RecordingIndex

use std::io::{BufReader, Seek, SeekFrom};
use std::path::{Path, PathBuf};

use super::format::Record;
use super::reader::{ReadError, RecordingReader};

/// Why a source's records cannot be read (any further).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SourceError {
    #[error("cannot open {path}: {source}")]
    Open {
        path: PathBuf,
        source: std::io::Error,
    },
    /// A `.prec` file's reader stopped.
    #[error(transparent)]
    Prec(#[from] ReadError),
    /// Another kind of file's reader stopped (`player_mcap`'s reader, say): `torn` when the file
    /// just ends early, as a crash while writing leaves it, rather than being damaged.
    #[error("{source}")]
    Other {
        torn: bool,
        source: Box<dyn std::error::Error + Send + Sync>,
    },
}

impl SourceError {
    /// Is this the end of a recording cut short (by a crash or a full disk) rather than damage
    /// in its middle?
    pub fn is_torn_tail(&self) -> bool {
        match self {
            SourceError::Prec(e) => e.is_torn_tail(),
            SourceError::Other { torn, .. } => *torn,
            SourceError::Open { .. } => false,
        }
    }
}

/// Where reading may resume: a record boundary, at `time_ns`. `offset` and `records` are what
/// the source's stream said of its position there ([`RecordStream::position`]): for a `.prec`
/// the byte offset and the records before it; a source that seeks by time may leave them 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SeekPoint {
    pub time_ns: u64,
    pub offset: u64,
    pub records: u64,
}

/// Records in the order they were written, one at a time.
pub trait RecordStream: Send {
    /// The next record; `Ok(None)` at a clean end. After an error, `Ok(None)`.
    fn next_record(&mut self) -> Result<Option<Record>, SourceError>;

    /// Where the next record starts: the `offset` and `records` of a [`SeekPoint`] there.
    fn position(&self) -> (u64, u64);
}

/// A recording that can be read from its start, and again from any seek point a reading from
/// the start noted.
pub trait RecordSource: Send + Sync {
    /// The file (or whatever it is) by name, for messages.
    fn name(&self) -> String;

    /// All the records, from the first.
    fn read(&self) -> Result<Box<dyn RecordStream>, SourceError>;

    /// The records from a seek point on: those at or after its place in the recording.
    fn read_from(&self, point: SeekPoint) -> Result<Box<dyn RecordStream>, SourceError>;
}

impl<S: RecordStream + ?Sized> RecordStream for Box<S> {
    fn next_record(&mut self) -> Result<Option<Record>, SourceError> {
        (**self).next_record()
    }

    fn position(&self) -> (u64, u64) {
        (**self).position()
    }
}

impl<R: std::io::Read + Send> RecordStream for RecordingReader<R> {
    fn next_record(&mut self) -> Result<Option<Record>, SourceError> {
        Ok(RecordingReader::next_record(self)?)
    }

    fn position(&self) -> (u64, u64) {
        (self.offset(), self.records())
    }
}

/// A `.prec` file: a seek point's offset is a byte offset in it.
#[derive(Debug, Clone)]
pub struct PrecFile {
    path: PathBuf,
}

impl PrecFile {
    /// Checks that the file opens as a recording.
    pub fn open(path: &Path) -> Result<Self, SourceError> {
        super::open(path)?;
        Ok(PrecFile {
            path: path.to_path_buf(),
        })
    }
}

impl RecordSource for PrecFile {
    fn name(&self) -> String {
        self.path.display().to_string()
    }

    fn read(&self) -> Result<Box<dyn RecordStream>, SourceError> {
        Ok(Box::new(super::open(&self.path)?))
    }

    fn read_from(&self, point: SeekPoint) -> Result<Box<dyn RecordStream>, SourceError> {
        let open = |source| SourceError::Open {
            path: self.path.clone(),
            source,
        };
        let mut file = std::fs::File::open(&self.path).map_err(open)?;
        file.seek(SeekFrom::Start(point.offset)).map_err(open)?;
        Ok(Box::new(RecordingReader::resume(
            BufReader::new(file),
            point.offset,
            point.records,
        )))
    }
}

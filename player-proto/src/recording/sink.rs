//! Where a [`super::Recorder`] writes: anything that appends records, flushes when the queue
//! runs dry and ends the file. A `.prec` ([`RecordingWriter`]) is one; another file format (an
//! MCAP file, in `player-mcap`) is another, so a recording can be written straight into it.

use std::io::Write;

use super::format::Record;
use super::writer::{RecordingWriter, WriteError};

/// A destination for records, driven by the recorder's writer thread.
pub trait RecordSink: Send + 'static {
    /// The error of a write; its text is what the recorder reports.
    type Error: std::error::Error;

    fn write(&mut self, record: &Record) -> Result<(), Self::Error>;

    /// Called whenever nothing is waiting: make what was written safe from a crash, as far as
    /// the format allows.
    fn flush(&mut self) -> Result<(), Self::Error>;

    /// Ends the file (an index or summary, if the format has one) after the last record.
    fn finish(&mut self) -> Result<(), Self::Error>;

    /// Bytes written so far, as far as the sink knows.
    fn bytes(&self) -> u64;
}

impl<W: Write + Send + 'static> RecordSink for RecordingWriter<W> {
    type Error = WriteError;

    fn write(&mut self, record: &Record) -> Result<(), WriteError> {
        RecordingWriter::write(self, record)
    }

    fn flush(&mut self) -> Result<(), WriteError> {
        RecordingWriter::flush(self)
    }

    /// A `.prec` has no end marker: every record is whole once flushed.
    fn finish(&mut self) -> Result<(), WriteError> {
        RecordingWriter::flush(self)
    }

    fn bytes(&self) -> u64 {
        RecordingWriter::bytes(self)
    }
}

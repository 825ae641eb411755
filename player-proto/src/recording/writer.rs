//! Writing a recording: the file header once, then records appended one after another.
//!
//! Nothing written is ever rewritten, so a crash or a full disk leaves every record before the
//! failing one intact; the failing one is a torn tail the reader reports.

use std::io::{self, Write};

use super::format::{FILE_HEADER_LEN, MAGIC, MAX_PAYLOAD, Record, VERSION};

/// Why a record could not be written.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    #[error(
        "writing the recording failed at byte {offset} (after {records} whole records): {source}"
    )]
    Io {
        offset: u64,
        records: u64,
        source: io::Error,
    },
    #[error("a {length}-byte record is above the format's {MAX_PAYLOAD}-byte limit")]
    TooLarge { length: usize },
}

/// Appends records to `W` (give it a buffered writer; see [`super::Recorder`]).
#[derive(Debug)]
pub struct RecordingWriter<W: Write> {
    out: W,
    /// Bytes handed to `out` so far.
    offset: u64,
    records: u64,
}

impl<W: Write> RecordingWriter<W> {
    /// Writes the file header.
    pub fn new(mut out: W) -> Result<Self, WriteError> {
        let mut header = [0u8; FILE_HEADER_LEN];
        header[..MAGIC.len()].copy_from_slice(&MAGIC);
        header[MAGIC.len()..].copy_from_slice(&VERSION.to_be_bytes());
        out.write_all(&header).map_err(|source| WriteError::Io {
            offset: 0,
            records: 0,
            source,
        })?;
        Ok(RecordingWriter {
            out,
            offset: FILE_HEADER_LEN as u64,
            records: 0,
        })
    }

    /// Appends one record: length, payload, checksum.
    pub fn write(&mut self, record: &Record) -> Result<(), WriteError> {
        let length = record.payload_len();
        if length > MAX_PAYLOAD {
            return Err(WriteError::TooLarge { length });
        }
        let fixed = record.fixed();
        let (head, body) = record.data();
        let mut crc = crc32fast::Hasher::new();
        crc.update(&fixed);
        crc.update(&head);
        crc.update(body);
        let length_field = u32::try_from(length).expect("below MAX_PAYLOAD");
        let parts: [&[u8]; 5] = [
            &length_field.to_be_bytes(),
            &fixed,
            &head,
            body,
            &crc.finalize().to_be_bytes(),
        ];
        for part in parts {
            self.out
                .write_all(part)
                .map_err(|source| self.failed(source))?;
        }
        self.offset += (super::format::LENGTH_LEN + length + super::format::CHECKSUM_LEN) as u64;
        self.records += 1;
        Ok(())
    }

    /// Pushes buffered records to the file.
    pub fn flush(&mut self) -> Result<(), WriteError> {
        self.out.flush().map_err(|source| self.failed(source))
    }

    /// Bytes written (file header included), as far as this writer knows.
    pub fn bytes(&self) -> u64 {
        self.offset
    }

    pub fn records(&self) -> u64 {
        self.records
    }

    pub fn into_inner(self) -> W {
        self.out
    }

    fn failed(&self, source: io::Error) -> WriteError {
        WriteError::Io {
            offset: self.offset,
            records: self.records,
            source,
        }
    }
}

//! Reading a recording back, record by record, trusting nothing: a torn tail (a crash while
//! writing), a damaged record or a file that is not a recording is an error naming the byte
//! offset and how many whole records came before it. Memory grows only with the bytes actually
//! read, whatever a length field claims.

use std::io::{self, Read};

use bytes::Bytes;

use super::format::{
    CHECKSUM_LEN, FILE_HEADER_LEN, LENGTH_LEN, MAGIC, MAX_PAYLOAD, Record, VERSION,
};

/// Why a recording cannot be read (any further).
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    #[error("reading the recording at byte {offset}: {source}")]
    Io { offset: u64, source: io::Error },
    #[error("not a recording: it starts with {found:02x?}, not the recording magic")]
    NotARecording { found: Vec<u8> },
    #[error("recording format version {found}; this program reads version {VERSION}")]
    UnsupportedVersion { found: u32 },
    #[error(
        "the recording stops inside the record at byte {offset} (after {records} whole records; {have} of its {need} bytes are there): a torn tail, as a crash while writing leaves"
    )]
    Truncated {
        offset: u64,
        records: u64,
        need: u64,
        have: u64,
    },
    #[error(
        "record at byte {offset} (after {records} whole records) claims {length} bytes, above the format's {MAX_PAYLOAD}-byte limit: the file is damaged"
    )]
    TooLarge {
        offset: u64,
        records: u64,
        length: u64,
    },
    #[error(
        "record at byte {offset} (after {records} whole records) fails its checksum: the file is damaged"
    )]
    Checksum { offset: u64, records: u64 },
    #[error("record at byte {offset} (after {records} whole records): {reason}")]
    BadRecord {
        offset: u64,
        records: u64,
        reason: super::RecordError,
    },
}

impl ReadError {
    /// Is this the end of a recording cut short (by a crash or a full disk) rather than damage
    /// in its middle?
    pub fn is_torn_tail(&self) -> bool {
        matches!(self, ReadError::Truncated { .. })
    }
}

/// Reads records from `R` (give it a buffered reader).
#[derive(Debug)]
pub struct RecordingReader<R: Read> {
    inner: R,
    /// Offset of the next unread byte.
    offset: u64,
    records: u64,
    /// An error was returned; nothing more is read.
    stopped: bool,
}

impl<R: Read> RecordingReader<R> {
    /// Checks the file header.
    pub fn new(mut inner: R) -> Result<Self, ReadError> {
        let mut header = Vec::with_capacity(FILE_HEADER_LEN);
        let got = read_up_to(&mut inner, &mut header, FILE_HEADER_LEN as u64)
            .map_err(|source| ReadError::Io { offset: 0, source })?;
        if got < MAGIC.len() || header[..MAGIC.len()] != MAGIC {
            return Err(ReadError::NotARecording { found: header });
        }
        if got < FILE_HEADER_LEN {
            return Err(ReadError::Truncated {
                offset: 0,
                records: 0,
                need: FILE_HEADER_LEN as u64,
                have: got as u64,
            });
        }
        let found = u32::from_be_bytes(header[MAGIC.len()..].try_into().expect("4 bytes"));
        if found != VERSION {
            return Err(ReadError::UnsupportedVersion { found });
        }
        Ok(RecordingReader {
            inner,
            offset: FILE_HEADER_LEN as u64,
            records: 0,
            stopped: false,
        })
    }

    /// A reader of `inner` positioned at a record boundary, `offset` bytes into the file after
    /// `records` records (a place an earlier reading noted, for seeking).
    pub fn resume(inner: R, offset: u64, records: u64) -> Self {
        RecordingReader {
            inner,
            offset,
            records,
            stopped: false,
        }
    }

    /// The next record; `Ok(None)` at a clean end (the file ends between records).
    pub fn next_record(&mut self) -> Result<Option<Record>, ReadError> {
        if self.stopped {
            return Ok(None);
        }
        let result = self.read_record();
        match &result {
            Ok(Some(_)) => self.records += 1,
            Ok(None) | Err(_) => self.stopped = true,
        }
        result
    }

    /// Offset of the next record (after the last one returned).
    pub fn offset(&self) -> u64 {
        self.offset
    }

    /// Whole records returned so far.
    pub fn records(&self) -> u64 {
        self.records
    }

    fn read_record(&mut self) -> Result<Option<Record>, ReadError> {
        let start = self.offset;
        let (offset, records) = (start, self.records);
        let mut length = Vec::with_capacity(LENGTH_LEN);
        let got = self.read_part(&mut length, LENGTH_LEN as u64)?;
        if got == 0 {
            return Ok(None);
        }
        let truncated = |have: usize, need: u64| ReadError::Truncated {
            offset,
            records,
            need,
            have: have as u64,
        };
        if got < LENGTH_LEN {
            return Err(truncated(got, LENGTH_LEN as u64));
        }
        let payload_len = u64::from(u32::from_be_bytes(length[..].try_into().expect("4")));
        if payload_len > MAX_PAYLOAD as u64 {
            return Err(ReadError::TooLarge {
                offset,
                records,
                length: payload_len,
            });
        }
        let need = (LENGTH_LEN + CHECKSUM_LEN) as u64 + payload_len;
        // Grows with what arrives, never to a size read from the file.
        let mut rest = Vec::new();
        let got = self.read_part(&mut rest, payload_len + CHECKSUM_LEN as u64)?;
        if (got as u64) < payload_len + CHECKSUM_LEN as u64 {
            return Err(truncated(LENGTH_LEN + got, need));
        }
        let checksum_at = rest.len() - CHECKSUM_LEN;
        let stored = u32::from_be_bytes(rest[checksum_at..].try_into().expect("4"));
        rest.truncate(checksum_at);
        if crc32fast::hash(&rest) != stored {
            return Err(ReadError::Checksum { offset, records });
        }
        Record::parse(Bytes::from(rest))
            .map(Some)
            .map_err(|reason| ReadError::BadRecord {
                offset,
                records,
                reason,
            })
    }

    /// Reads up to `limit` bytes into `out`, advancing the offset.
    fn read_part(&mut self, out: &mut Vec<u8>, limit: u64) -> Result<usize, ReadError> {
        let got = read_up_to(&mut self.inner, out, limit).map_err(|source| ReadError::Io {
            offset: self.offset,
            source,
        })?;
        self.offset += got as u64;
        Ok(got)
    }
}

impl<R: Read> Iterator for RecordingReader<R> {
    type Item = Result<Record, ReadError>;

    fn next(&mut self) -> Option<Self::Item> {
        self.next_record().transpose()
    }
}

/// Reads until `limit` bytes or the end of the input; returns how many.
fn read_up_to<R: Read>(input: &mut R, out: &mut Vec<u8>, limit: u64) -> io::Result<usize> {
    let got = input.by_ref().take(limit).read_to_end(out)?;
    Ok(got)
}

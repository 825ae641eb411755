//! An MCAP file written from a recording, read as a [`RecordSource`] directly: from its start by
//! the linear reader (which also reads a file cut short), and from a seek point through the
//! file's own chunk index, reading only the chunks at or after the point's time. A file without
//! a summary (a recorder that crashed) is read linearly to the point instead.

use std::collections::HashMap;
use std::fs::File;
use std::io::{BufReader, Read, Seek, SeekFrom};
use std::path::{Path, PathBuf};

use mcap::sans_io::indexed_reader::{
    IndexedReadEvent, IndexedReader, IndexedReaderOptions, ReadOrder,
};
use mcap::sans_io::summary_reader::{SummaryReadEvent, SummaryReader};
use player_proto::recording::index::SeekPoint;
use player_proto::recording::{Record, RecordSource, RecordStream, SourceError};

use crate::layout::{FILE_METADATA, Stream, player_channel};
use crate::reader::{McapReadError, McapRecords, RECORD_LIMIT, to_event};

/// Why an MCAP file's chunks cannot be read through its index.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum IndexedReadError {
    #[error("reading chunk data at byte {offset}: {source}")]
    Io { offset: u64, source: std::io::Error },
    #[error(
        "the chunk index claims {length} bytes at byte {offset}, above the {RECORD_LIMIT}-byte limit"
    )]
    TooLarge { offset: u64, length: usize },
    #[error("through the chunk index: {0}")]
    Mcap(#[from] mcap::McapError),
    #[error("message {index} of channel {topic:?}: {reason}")]
    BadMessage {
        topic: String,
        index: u64,
        reason: crate::layout::LayoutError,
    },
}

/// Opens a recording whichever kind of file holds it: an MCAP file (by its first bytes) or a
/// `.prec`.
pub fn open_recording(path: &Path) -> Result<Box<dyn RecordSource>, SourceError> {
    if crate::is_mcap(path) {
        Ok(Box::new(McapFile::open(path)?))
    } else {
        Ok(Box::new(player_proto::recording::PrecFile::open(path)?))
    }
}

/// An MCAP file holding a recording.
pub struct McapFile {
    path: PathBuf,
    /// The file's summary, when it has one with chunk indexes (a file closed properly).
    summary: Option<mcap::Summary>,
}

impl McapFile {
    /// Opens `path` and reads its summary, if it has one.
    pub fn open(path: &Path) -> Result<McapFile, SourceError> {
        let mut file = open(path)?;
        let summary = match read_summary(&mut file) {
            Ok(Some(summary)) if !summary.chunk_indexes.is_empty() => Some(summary),
            Ok(_) => None,
            Err(e) => {
                tracing::debug!(
                    "{}: no usable summary ({e}): seeking reads linearly",
                    path.display()
                );
                None
            }
        };
        if let Some(summary) = &summary {
            let player = summary
                .channels
                .values()
                .any(|c| player_channel(&c.metadata).is_some());
            let marked = summary
                .metadata_indexes
                .iter()
                .any(|m| m.name == FILE_METADATA);
            if !player && !marked {
                return Err(other(McapReadError::NoPlayerChannels {
                    channels: summary.channels.len(),
                }));
            }
        }
        Ok(McapFile {
            path: path.to_path_buf(),
            summary,
        })
    }

    /// Can a seek read only the chunks it needs?
    pub fn indexed(&self) -> bool {
        self.summary.is_some()
    }
}

impl RecordSource for McapFile {
    fn name(&self) -> String {
        self.path.display().to_string()
    }

    fn read(&self) -> Result<Box<dyn RecordStream>, SourceError> {
        Ok(Box::new(McapRecords::new(BufReader::new(open(
            &self.path,
        )?))))
    }

    fn read_from(&self, point: SeekPoint) -> Result<Box<dyn RecordStream>, SourceError> {
        let file = open(&self.path)?;
        let Some(summary) = &self.summary else {
            return Ok(Box::new(Skipping {
                records: McapRecords::new(BufReader::new(file)),
                from_ns: point.time_ns,
            }));
        };
        let options = IndexedReaderOptions::new()
            .with_order(ReadOrder::File)
            .starting_at(point.time_ns)
            .with_record_length_limit(RECORD_LIMIT);
        let reader = IndexedReader::new_with_options(summary, options).map_err(other)?;
        let channels = summary
            .channels
            .iter()
            .map(|(&id, c)| {
                let player = player_channel(&c.metadata).and_then(Result::ok);
                let channel = SummaryChannel {
                    topic: c.topic.clone(),
                    player,
                    messages: 0,
                };
                (id, channel)
            })
            .collect();
        Ok(Box::new(Indexed {
            file,
            reader,
            channels,
            records: point.records,
            chunk: Vec::new(),
            stopped: false,
        }))
    }
}

impl<R: Read + Send> RecordStream for McapRecords<R> {
    fn next_record(&mut self) -> Result<Option<Record>, SourceError> {
        McapRecords::next_record(self).map_err(|e| {
            let torn = matches!(
                &e,
                McapReadError::Mcap {
                    source: mcap::McapError::UnexpectedEof,
                    ..
                }
            );
            SourceError::Other {
                torn,
                source: Box::new(e),
            }
        })
    }

    fn position(&self) -> (u64, u64) {
        (0, self.records())
    }
}

/// A linear reading that skips the records before a time: a seek in a file without an index.
struct Skipping {
    records: McapRecords<BufReader<File>>,
    from_ns: u64,
}

impl RecordStream for Skipping {
    fn next_record(&mut self) -> Result<Option<Record>, SourceError> {
        loop {
            match RecordStream::next_record(&mut self.records)? {
                Some(record) if record.time_ns < self.from_ns => {}
                other => return Ok(other),
            }
        }
    }

    fn position(&self) -> (u64, u64) {
        self.records.position()
    }
}

/// A channel the summary declares.
struct SummaryChannel {
    topic: String,
    /// The connection and stream; `None` for a channel that is not a recording's.
    player: Option<(u32, Stream)>,
    /// Messages read from it so far.
    messages: u64,
}

/// A reading through the chunk index, in file order, from a time on.
struct Indexed {
    file: File,
    reader: IndexedReader,
    /// By channel id.
    channels: HashMap<u16, SummaryChannel>,
    records: u64,
    /// The compressed bytes of the chunk being inserted (reused).
    chunk: Vec<u8>,
    stopped: bool,
}

impl Indexed {
    fn read_record(&mut self) -> Result<Option<Record>, IndexedReadError> {
        loop {
            match self.reader.next_event() {
                None => return Ok(None),
                Some(Err(e)) => return Err(e.into()),
                Some(Ok(IndexedReadEvent::ReadChunkRequest { offset, length })) => {
                    if length > RECORD_LIMIT {
                        return Err(IndexedReadError::TooLarge { offset, length });
                    }
                    self.chunk.resize(length, 0);
                    let io = |source| IndexedReadError::Io { offset, source };
                    self.file.seek(SeekFrom::Start(offset)).map_err(io)?;
                    self.file.read_exact(&mut self.chunk).map_err(io)?;
                    self.reader.insert_chunk_record_data(offset, &self.chunk)?;
                }
                Some(Ok(IndexedReadEvent::Message { header, data })) => {
                    // The summary declared every channel a chunk index points into; a message on
                    // another is no recording's and is passed over, as the linear reader does.
                    let Some(channel) = self.channels.get_mut(&header.channel_id) else {
                        continue;
                    };
                    let index = channel.messages;
                    channel.messages += 1;
                    let Some((connection, stream)) = channel.player else {
                        continue;
                    };
                    let event =
                        to_event(stream, data).map_err(|reason| IndexedReadError::BadMessage {
                            topic: channel.topic.clone(),
                            index,
                            reason,
                        })?;
                    return Ok(Some(Record {
                        time_ns: header.log_time,
                        connection,
                        event,
                    }));
                }
            }
        }
    }
}

impl RecordStream for Indexed {
    fn next_record(&mut self) -> Result<Option<Record>, SourceError> {
        if self.stopped {
            return Ok(None);
        }
        match self.read_record() {
            Ok(Some(record)) => {
                self.records += 1;
                Ok(Some(record))
            }
            Ok(None) => {
                self.stopped = true;
                Ok(None)
            }
            Err(e) => {
                self.stopped = true;
                Err(other(e))
            }
        }
    }

    fn position(&self) -> (u64, u64) {
        (0, self.records)
    }
}

fn open(path: &Path) -> Result<File, SourceError> {
    File::open(path).map_err(|source| SourceError::Open {
        path: path.to_path_buf(),
        source,
    })
}

fn other(e: impl std::error::Error + Send + Sync + 'static) -> SourceError {
    SourceError::Other {
        torn: false,
        source: Box::new(e),
    }
}

/// The file's summary section, `None` when it has none (a file cut short has no footer).
pub(crate) fn read_summary(file: &mut File) -> Result<Option<mcap::Summary>, mcap::McapError> {
    let size = file.seek(SeekFrom::End(0))?;
    // The summary reader parses what it reads as the lengths claim: checked first.
    summary_lengths(file, size)?;
    let options = mcap::sans_io::summary_reader::SummaryReaderOptions::default()
        .with_file_size(size)
        .with_record_length_limit(RECORD_LIMIT);
    let mut reader = SummaryReader::new_with_options(options);
    while let Some(event) = reader.next_event() {
        match event? {
            SummaryReadEvent::ReadRequest(need) => {
                let piece = reader.insert(need.min(RECORD_LIMIT));
                let got = file.read(piece)?;
                reader.notify_read(got);
            }
            SummaryReadEvent::SeekRequest(to) => {
                let at = file.seek(to)?;
                reader.notify_seeked(at);
            }
        }
    }
    Ok(reader.finish())
}

/// Checks every record of the file's summary section (from the footer's `summary_start` to the
/// footer) with [`record_lengths::check`]: a length past its record is an error, and the file
/// is then read without its index. A file without a footer or a summary passes: the summary
/// reader finds none.
fn summary_lengths(file: &mut File, size: u64) -> Result<(), mcap::McapError> {
    // The footer record (opcode, length, 20 bytes), then the closing magic.
    const FOOTER: usize = 1 + 8 + 20;
    let end = FOOTER + crate::MAGIC.len();
    let Some(footer) = size.checked_sub(end as u64) else {
        return Ok(());
    };
    let mut tail = vec![0u8; end];
    file.seek(SeekFrom::Start(footer))?;
    file.read_exact(&mut tail)?;
    // No footer (a file cut short): nothing to check; the summary reader says so itself.
    if tail[0] != 0x02 || &tail[FOOTER..] != crate::MAGIC {
        return Ok(());
    }
    let start = u64::from_le_bytes(tail[9..17].try_into().expect("8 bytes"));
    let damaged = |reason: String| mcap::McapError::Io(std::io::Error::other(reason));
    // No summary, or an empty one ending at the footer.
    if start == 0 || start == footer {
        return Ok(());
    }
    // Past the footer's start the summary reader would parse the footer's own bytes and the
    // closing magic as records, unchecked.
    if start > footer {
        return Err(damaged(format!(
            "the summary starts at byte {start}, past the footer at byte {footer}"
        )));
    }
    file.seek(SeekFrom::Start(start))?;
    // A long recording's summary holds thousands of small chunk indexes: read in pieces.
    let mut input = BufReader::new(&mut *file);
    let mut at = start;
    let mut body = Vec::new();
    while at < footer {
        let mut head = [0u8; 9];
        input.read_exact(&mut head)?;
        let length = u64::from_le_bytes(head[1..].try_into().expect("8 bytes"));
        let left = footer - at - 9;
        if length > left || length > RECORD_LIMIT as u64 {
            return Err(damaged(format!(
                "a summary record at byte {at} claims {length} bytes, {left} remain before the footer"
            )));
        }
        if !crate::record_lengths::in_summary(head[0]) {
            return Err(damaged(format!(
                "a record of opcode {:#04x} at byte {at} in the summary section",
                head[0]
            )));
        }
        body.resize(length as usize, 0);
        input.read_exact(&mut body)?;
        crate::record_lengths::check(head[0], &body)
            .map_err(|e| damaged(format!("the summary record at byte {at}: {e}")))?;
        at += 9 + length;
    }
    Ok(())
}

//! Reading a recording's records back out of an MCAP file, in file order, trusting nothing:
//! the file is read in small pieces so memory grows only with the bytes that are there,
//! whatever a length field claims; damage, a cut and a foreign file are errors naming the
//! channel, the message and the byte, after every whole record before them was returned.

use std::collections::HashMap;
use std::io::{ErrorKind, Read};

use bytes::Bytes;
use mcap::sans_io::linear_reader::{LinearReadEvent, LinearReader, LinearReaderOptions};
use player_proto::capture::Direction;
use player_proto::recording::format::MAX_PAYLOAD;
use player_proto::recording::{Event, Record};
use player_proto::wire::{HEADER_LEN, Header};

use crate::layout::{FILE_METADATA, LayoutError, Stream, parse_session, player_channel};

/// Bytes read from the file at a time.
const READ_PIECE: usize = 64 * 1024;
/// The largest MCAP record (a chunk, decompressed) accepted: a chunk holds up to the writer's
/// chunk size plus one message, and a message is at most a recording's largest record.
pub(crate) const RECORD_LIMIT: usize = MAX_PAYLOAD + 16 * 1024 * 1024;

/// Why the records of an MCAP file cannot be read (any further).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum McapReadError {
    #[error("reading the MCAP file at byte {offset}: {source}")]
    Io { offset: u64, source: std::io::Error },
    #[error(
        "the MCAP file is cut short or damaged at or before byte {offset} (after {records} whole Player records): {source}"
    )]
    Mcap {
        offset: u64,
        records: u64,
        source: mcap::McapError,
    },
    #[error(
        "channel {topic:?} (id {channel}), declared at or before byte {offset}, is not a Player channel it claims to be: {reason}"
    )]
    BadChannel {
        topic: String,
        channel: u16,
        offset: u64,
        reason: LayoutError,
    },
    #[error(
        "message {index} of channel {topic:?} (record {records} of the recording, at or before byte {offset}): {reason}"
    )]
    BadMessage {
        topic: String,
        index: u64,
        records: u64,
        offset: u64,
        reason: LayoutError,
    },
    #[error(
        "message {index} of channel {topic:?} (at or before byte {offset}) is record {found} of the recording, but {records} records came before it: the records between are missing (damage the MCAP reader passed over, such as a chunk whose opcode changed)"
    )]
    OutOfSequence {
        topic: String,
        index: u64,
        records: u64,
        found: u32,
        offset: u64,
    },
    #[error(
        "a record at or before byte {offset} (after {records} whole Player records) is damaged: {reason}"
    )]
    LengthPastRecord {
        offset: u64,
        records: u64,
        reason: crate::record_lengths::LengthPastRecord,
    },
    #[error(
        "a message at or before byte {offset} is on channel id {channel}, which no channel record declared"
    )]
    UnknownChannel { channel: u16, offset: u64 },
    #[error(
        "the MCAP file is not a Player recording: none of its {channels} channels carries player.connection metadata, and it has no {FILE_METADATA:?} metadata record"
    )]
    NoPlayerChannels { channels: usize },
}

/// A channel as the reader knows it.
struct Channel {
    topic: String,
    /// `None` for a channel that is not a recording's (Foxglove's, another tool's).
    player: Option<(u32, Stream)>,
    messages: u64,
}

/// The records of an MCAP file written by [`crate::McapRecordWriter`], in the order written.
pub struct McapRecords<R: Read> {
    input: R,
    reader: LinearReader,
    channels: HashMap<u16, Channel>,
    /// Bytes handed to the MCAP reader so far.
    offset: u64,
    records: u64,
    stopped: bool,
    /// The file has the metadata record our writer starts with.
    marked: bool,
}

impl<R: Read> McapRecords<R> {
    pub fn new(input: R) -> Self {
        let options = LinearReaderOptions::default()
            .with_prevalidate_chunk_crcs(true)
            .with_record_length_limit(RECORD_LIMIT);
        McapRecords {
            input,
            reader: LinearReader::new_with_options(options),
            channels: HashMap::new(),
            offset: 0,
            records: 0,
            stopped: false,
            marked: false,
        }
    }

    /// Records returned so far.
    pub fn records(&self) -> u64 {
        self.records
    }

    /// The next record; `Ok(None)` at the end of a whole file.
    pub fn next_record(&mut self) -> Result<Option<Record>, McapReadError> {
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

    fn read_record(&mut self) -> Result<Option<Record>, McapReadError> {
        loop {
            let event = match self.reader.next_event() {
                None => return self.at_end(),
                Some(Err(source)) => {
                    return Err(McapReadError::Mcap {
                        offset: self.offset,
                        records: self.records,
                        source,
                    });
                }
                Some(Ok(event)) => event,
            };
            let (opcode, data) = match event {
                LinearReadEvent::ReadRequest(need) => {
                    // Never more than a piece at a time, whatever the file claims to need.
                    let piece = self.reader.insert(need.clamp(1, READ_PIECE));
                    let got =
                        read_some(&mut self.input, piece).map_err(|source| McapReadError::Io {
                            offset: self.offset,
                            source,
                        })?;
                    self.reader.notify_read(got);
                    self.offset += got as u64;
                    continue;
                }
                LinearReadEvent::Record { opcode, data } => (opcode, data),
            };
            let offset = self.offset;
            let mcap_error = |source| McapReadError::Mcap {
                offset,
                records: self.records,
                source,
            };
            // The parser reserves what a record's lengths claim: they are checked first.
            crate::record_lengths::check(opcode, data).map_err(|reason| {
                McapReadError::LengthPastRecord {
                    offset,
                    records: self.records,
                    reason,
                }
            })?;
            match mcap::parse_record(opcode, data).map_err(mcap_error)? {
                mcap::records::Record::Channel(channel) => {
                    let player = match player_channel(&channel.metadata) {
                        None => None,
                        Some(Ok(found)) => Some(found),
                        Some(Err(reason)) => {
                            return Err(McapReadError::BadChannel {
                                topic: channel.topic,
                                channel: channel.id,
                                offset,
                                reason,
                            });
                        }
                    };
                    self.channels.insert(
                        channel.id,
                        Channel {
                            topic: channel.topic,
                            player,
                            messages: 0,
                        },
                    );
                }
                mcap::records::Record::Message { header, data } => {
                    let channel = self.channels.get_mut(&header.channel_id).ok_or(
                        McapReadError::UnknownChannel {
                            channel: header.channel_id,
                            offset,
                        },
                    )?;
                    let index = channel.messages;
                    channel.messages += 1;
                    let Some((connection, stream)) = channel.player else {
                        continue;
                    };
                    // Each Player message's sequence number is its record's place in the
                    // recording (modulo 2³², `layout.rs`): a gap is records lost, never a
                    // recording's beginning with its middle left out.
                    if header.sequence != self.records as u32 {
                        return Err(McapReadError::OutOfSequence {
                            topic: channel.topic.clone(),
                            index,
                            records: self.records,
                            found: header.sequence,
                            offset,
                        });
                    }
                    let event =
                        to_event(stream, &data).map_err(|reason| McapReadError::BadMessage {
                            topic: channel.topic.clone(),
                            index,
                            records: self.records,
                            offset,
                            reason,
                        })?;
                    return Ok(Some(Record {
                        time_ns: header.log_time,
                        connection,
                        event,
                    }));
                }
                mcap::records::Record::Metadata(metadata) => {
                    self.marked |= metadata.name == FILE_METADATA;
                }
                _ => {}
            }
        }
    }

    fn at_end(&self) -> Result<Option<Record>, McapReadError> {
        if self.marked || self.channels.values().any(|c| c.player.is_some()) {
            Ok(None)
        } else {
            Err(McapReadError::NoPlayerChannels {
                channels: self.channels.len(),
            })
        }
    }
}

impl<R: Read> Iterator for McapRecords<R> {
    type Item = Result<Record, McapReadError>;

    fn next(&mut self) -> Option<Self::Item> {
        self.next_record().transpose()
    }
}

/// The event an MCAP message of a Player stream carries.
pub(crate) fn to_event(stream: Stream, data: &[u8]) -> Result<Event, LayoutError> {
    let direction = match stream {
        Stream::Session => return parse_session(data),
        Stream::ToClient => Direction::ServerToClient,
        Stream::ToServer => Direction::ClientToServer,
    };
    let header = match Header::decode_slice(data) {
        None => return Err(LayoutError::NoHeader(data.len())),
        Some(Err(e)) => return Err(LayoutError::Header(e)),
        Some(Ok(header)) => header,
    };
    let body = &data[HEADER_LEN..];
    if body.len() != header.size as usize {
        return Err(LayoutError::BodySize {
            announced: header.size,
            holds: body.len(),
        });
    }
    Ok(Event::Message {
        direction,
        header,
        body: Bytes::copy_from_slice(body),
    })
}

/// One read, retried when interrupted; 0 at the end.
fn read_some<R: Read>(input: &mut R, buf: &mut [u8]) -> std::io::Result<usize> {
    loop {
        match input.read(buf) {
            Err(e) if e.kind() == ErrorKind::Interrupted => {}
            other => return other,
        }
    }
}

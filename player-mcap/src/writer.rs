//! Writing a recording's records into an MCAP file, losslessly (see [`crate::layout`]), with
//! Foxglove's well-known schemas beside them when asked (`crate::foxglove_channels`, with the
//! `foxglove` feature).

use std::collections::HashMap;
use std::io::{Seek, Write};

use mcap::records::MessageHeader;
use player_proto::recording::{Event, Record};

#[cfg(feature = "foxglove")]
use crate::foxglove_channels::FoxgloveChannels;
use crate::layout::{FILE_METADATA, Stream, session_json};

/// Why an MCAP file could not be written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum McapWriteError {
    #[error("writing the MCAP file (after {records} records): {source}")]
    Mcap {
        records: u64,
        source: mcap::McapError,
    },
    #[error("more channels than an MCAP file can name (65 535) at connection {connection}")]
    TooManyChannels { connection: u32 },
}

/// How the file is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct McapOptions {
    /// Also write what Foxglove shows of the messages, in its well-known schemas (the
    /// `foxglove` feature).
    #[cfg(feature = "foxglove")]
    pub foxglove: bool,
    /// Uncompressed bytes per chunk: what a crash can lose while recording directly.
    pub chunk_size: u64,
}

impl Default for McapOptions {
    fn default() -> Self {
        McapOptions {
            #[cfg(feature = "foxglove")]
            foxglove: true,
            chunk_size: mcap::WriteOptions::DEFAULT_CHUNK_SIZE,
        }
    }
}

/// Appends records to an MCAP file; [`McapRecordWriter::finish`] writes its index.
pub struct McapRecordWriter<W: Write + Seek> {
    out: mcap::Writer<W>,
    channels: HashMap<(u32, Stream), u16>,
    schemas: HashMap<Stream, u16>,
    /// Host and port of each connection, from its `connection` record.
    hosts: HashMap<u32, (String, u16)>,
    #[cfg(feature = "foxglove")]
    foxglove: Option<FoxgloveChannels>,
    records: u64,
}

impl<W: Write + Seek> McapRecordWriter<W> {
    /// Starts the file: header and the metadata record that marks it as a Player recording.
    pub fn new(out: W, options: McapOptions) -> Result<Self, McapWriteError> {
        let fail = |source| McapWriteError::Mcap { records: 0, source };
        let mut out = mcap::WriteOptions::new()
            .library(concat!("pv3d player-mcap ", env!("CARGO_PKG_VERSION")))
            .chunk_size(Some(options.chunk_size))
            .create(out)
            .map_err(fail)?;
        let format = player_proto::recording::format::VERSION.to_string();
        out.write_metadata(&mcap::records::Metadata {
            name: FILE_METADATA.into(),
            metadata: [("prec_version".to_string(), format)].into(),
        })
        .map_err(fail)?;
        Ok(McapRecordWriter {
            out,
            channels: HashMap::new(),
            schemas: HashMap::new(),
            hosts: HashMap::new(),
            #[cfg(feature = "foxglove")]
            foxglove: options.foxglove.then(FoxgloveChannels::default),
            records: 0,
        })
    }

    /// Appends one record (and what Foxglove shows of it).
    pub fn write(&mut self, record: &Record) -> Result<(), McapWriteError> {
        let stream = Stream::of(&record.event);
        let channel = self.channel(record, stream)?;
        let header = MessageHeader {
            channel_id: channel,
            // The record's place in the recording; wraps after 2³² records.
            sequence: self.records as u32,
            log_time: record.time_ns,
            publish_time: record.time_ns,
        };
        let written = match &record.event {
            Event::Message {
                header: h, body, ..
            } => {
                let mut data = Vec::with_capacity(player_proto::wire::HEADER_LEN + body.len());
                h.encode(&mut data);
                data.extend_from_slice(body);
                self.out.write_to_known_channel(&header, &data)
            }
            event => {
                let json = session_json(event).expect("not a message");
                self.out.write_to_known_channel(&header, &json)
            }
        };
        written.map_err(|source| self.failed(source))?;
        self.records += 1;
        #[cfg(feature = "foxglove")]
        if let Some(foxglove) = &mut self.foxglove {
            let records = self.records;
            foxglove
                .write(&mut self.out, record)
                .map_err(|source| McapWriteError::Mcap { records, source })?;
        }
        Ok(())
    }

    /// Records written so far.
    pub fn records(&self) -> u64 {
        self.records
    }

    /// Foxglove messages written so far (none without the `foxglove` feature).
    pub fn foxglove_messages(&self) -> u64 {
        #[cfg(feature = "foxglove")]
        return self.foxglove.as_ref().map_or(0, |f| f.written);
        #[cfg(not(feature = "foxglove"))]
        0
    }

    /// Writes what is buffered: every record so far is in the file after this.
    pub fn flush(&mut self) -> Result<(), McapWriteError> {
        self.out.flush().map_err(|source| self.failed(source))
    }

    /// Writes the index and summary and ends the file.
    pub fn finish(mut self) -> Result<W, McapWriteError> {
        self.out.finish().map_err(|source| self.failed(source))?;
        Ok(self.out.into_inner())
    }

    /// The channel of a connection's stream, added at its first record.
    fn channel(&mut self, record: &Record, stream: Stream) -> Result<u16, McapWriteError> {
        let connection = record.connection;
        if let Event::Connection { host, port } = &record.event {
            self.hosts.insert(connection, (host.clone(), *port));
        }
        if let Some(&id) = self.channels.get(&(connection, stream)) {
            return Ok(id);
        }
        let schema = match self.schemas.get(&stream) {
            Some(&id) => id,
            None => {
                let (name, encoding, data, _) = stream.schema();
                let id = self
                    .out
                    .add_schema(name, encoding, data)
                    .map_err(|source| self.failed(source))?;
                self.schemas.insert(stream, id);
                id
            }
        };
        let known = self.hosts.get(&connection).map(|(h, p)| (h.as_str(), *p));
        let metadata = stream.metadata(connection, known);
        let (_, _, _, message_encoding) = stream.schema();
        let id = self
            .out
            .add_channel(
                schema,
                &stream.topic(connection),
                message_encoding,
                &metadata,
            )
            .map_err(|source| match source {
                mcap::McapError::TooManyChannels => McapWriteError::TooManyChannels { connection },
                source => self.failed(source),
            })?;
        self.channels.insert((connection, stream), id);
        Ok(id)
    }

    fn failed(&self, source: mcap::McapError) -> McapWriteError {
        McapWriteError::Mcap {
            records: self.records,
            source,
        }
    }
}

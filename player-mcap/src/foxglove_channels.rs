//! The Foxglove side of an MCAP export: what `player_foxglove` makes of each message a server
//! sent, on channels named by topic with Foxglove's schemas, beside the raw records — so the
//! file opens in Foxglove, Lichtblick or any MCAP reader as scans, poses, transforms, maps,
//! images and scene entities. Connection events become `foxglove.Log` lines.

use std::collections::{BTreeMap, HashMap};
use std::io::{Seek, Write};

use foxglove::messages::log::Level;
use mcap::records::MessageHeader;
use player_foxglove::{Converter, MESSAGE_ENCODING, Output};
use player_proto::capture::Direction;
use player_proto::recording::{Event, Record};
use player_proto::wire::Banner;

/// Converts records and writes what they make.
#[derive(Debug, Default)]
pub struct FoxgloveChannels {
    converter: Converter,
    /// Each connection's robot name, `host:port`.
    robots: HashMap<u32, String>,
    schemas: HashMap<String, u16>,
    /// Channel id and the next sequence number, by topic.
    channels: HashMap<String, (u16, u32)>,
    /// Foxglove messages written.
    pub written: u64,
}

impl FoxgloveChannels {
    /// Writes what Foxglove shows of one record (often nothing).
    pub fn write<W: Write + Seek>(
        &mut self,
        out: &mut mcap::Writer<W>,
        record: &Record,
    ) -> mcap::McapResult<()> {
        let connection = record.connection;
        let robot = |robots: &HashMap<u32, String>| {
            robots
                .get(&connection)
                .cloned()
                .unwrap_or_else(|| format!("connection{connection}"))
        };
        let time = player_foxglove::frames::timestamp(record.time_ns as f64 / 1e9);
        let outputs = match &record.event {
            Event::Connection { host, port } => {
                self.robots.insert(connection, format!("{host}:{port}"));
                Vec::new()
            }
            Event::Opened { banner } => {
                let version = Banner::parse(banner).map_or_else(|e| e.to_string(), |b| b.version);
                let text = format!("connected (Player {version})");
                vec![player_foxglove::log(
                    &robot(&self.robots),
                    time,
                    Level::Info,
                    &text,
                )]
            }
            Event::Closed { why } => {
                let text = format!("disconnected: {why}");
                vec![player_foxglove::log(
                    &robot(&self.robots),
                    time,
                    Level::Warning,
                    &text,
                )]
            }
            Event::Message {
                direction: Direction::ServerToClient,
                header,
                body,
            } => self
                .converter
                .server_message(&robot(&self.robots), header, body),
            Event::Message { .. } => Vec::new(),
        };
        for output in outputs {
            self.put(out, record.time_ns, &output)?;
        }
        Ok(())
    }

    fn put<W: Write + Seek>(
        &mut self,
        out: &mut mcap::Writer<W>,
        time_ns: u64,
        output: &Output,
    ) -> mcap::McapResult<()> {
        let (channel, sequence) = match self.channels.get_mut(&output.topic) {
            Some(known) => known,
            None => {
                let schema = output.message.schema();
                let schema_id = match self.schemas.get(&schema.name) {
                    Some(&id) => id,
                    None => {
                        let id = out.add_schema(&schema.name, &schema.encoding, &schema.data)?;
                        self.schemas.insert(schema.name.clone(), id);
                        id
                    }
                };
                let id =
                    out.add_channel(schema_id, &output.topic, MESSAGE_ENCODING, &BTreeMap::new())?;
                self.channels.entry(output.topic.clone()).or_insert((id, 0))
            }
        };
        let header = MessageHeader {
            channel_id: *channel,
            sequence: *sequence,
            log_time: time_ns,
            publish_time: time_ns,
        };
        *sequence = sequence.wrapping_add(1);
        out.write_to_known_channel(&header, &output.message.encode())?;
        self.written += 1;
        Ok(())
    }
}

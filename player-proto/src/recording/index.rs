//! One pass over a recording for what replaying and summarising it need, without keeping its
//! messages: each connection's host, port, banner and devices (from the device list and driver
//! names the server gave, and any device that sent data), the replies its devices gave to
//! each request, the time span, and places to seek to.

use std::collections::{BTreeMap, HashMap};

use bytes::Bytes;

use super::format::{Event, Record};
pub use super::source::SeekPoint;
use super::source::{RecordSource, RecordStream, SourceError};
use crate::capture::Direction;
use crate::interfaces::player::{self, Player};
use crate::message::{Body, Message};
use crate::wire::{BANNER_LEN, Banner, Interface, MsgType};

/// Recorded time between two seek points, at most: seeking reads at most this much in vain.
pub const SEEK_EVERY_NS: u64 = 1_000_000_000;

/// A device as a recording knows it: interface and index (host and port are the connection's).
pub type DeviceKey = (Interface, u16);
/// A request as it was asked: device, subtype, body bytes.
pub type RequestKey = (Interface, u16, u8, Bytes);

/// One recorded connection.
#[derive(Debug, Clone, Default)]
pub struct ConnectionIndex {
    pub host: String,
    pub port: u16,
    /// The first banner the server sent.
    pub banner: Option<[u8; BANNER_LEN]>,
    /// Devices and driver names (empty when the recording never learnt it).
    pub devices: BTreeMap<DeviceKey, String>,
    /// DATA messages from each device.
    pub data: BTreeMap<DeviceKey, u64>,
    /// The last reply (ACK or NACK, and its body) to each request asked of a device.
    pub replies: HashMap<RequestKey, (MsgType, Bytes)>,
    /// Requests still waiting for their reply, by device and subtype.
    asked: HashMap<(Interface, u16, u8), Bytes>,
}

impl ConnectionIndex {
    /// The banner's version (`3.1.1-dev`), if there was a banner and it parses.
    pub fn version(&self) -> Option<String> {
        self.banner
            .as_ref()
            .and_then(|raw| Banner::parse(raw).ok())
            .map(|b| b.version)
    }
}

/// What a pass over a recording found.
#[derive(Debug, Default)]
pub struct RecordingIndex {
    /// By connection number.
    pub connections: BTreeMap<u32, ConnectionIndex>,
    /// Time of the first and last message record (0 when there is none).
    pub first_ns: u64,
    pub last_ns: u64,
    pub records: u64,
    pub messages: u64,
    /// In increasing time, the first at the first record.
    pub seek_points: Vec<SeekPoint>,
    /// Why reading stopped before the end of the file, if it did: everything before is indexed.
    pub stopped: Option<SourceError>,
}

impl RecordingIndex {
    /// Reads the whole recording from `source`; only opening it is an error.
    pub fn read(source: &dyn RecordSource) -> Result<RecordingIndex, SourceError> {
        Ok(RecordingIndex::build(source.read()?))
    }

    /// Reads the whole recording. A reader error ends the pass and is kept in `stopped`.
    pub fn build(mut reader: impl RecordStream) -> RecordingIndex {
        let mut index = RecordingIndex::default();
        loop {
            let (offset, records) = reader.position();
            match reader.next_record() {
                Ok(Some(record)) => index.add(&record, offset, records),
                Ok(None) => break,
                Err(e) => {
                    index.stopped = Some(e);
                    break;
                }
            }
        }
        index
    }

    /// Recorded seconds from the first message to the last.
    pub fn duration_s(&self) -> f64 {
        self.last_ns.saturating_sub(self.first_ns) as f64 / 1e9
    }

    /// The last seek point at or before `time_ns`.
    pub fn seek_point(&self, time_ns: u64) -> Option<SeekPoint> {
        let after = self.seek_points.partition_point(|p| p.time_ns <= time_ns);
        self.seek_points.get(after.saturating_sub(1)).copied()
    }

    fn add(&mut self, record: &Record, offset: u64, records: u64) {
        self.records += 1;
        let due = self
            .seek_points
            .last()
            .is_none_or(|p| record.time_ns >= p.time_ns.saturating_add(SEEK_EVERY_NS));
        if due {
            self.seek_points.push(SeekPoint {
                time_ns: record.time_ns,
                offset,
                records,
            });
        }
        let connection = self.connections.entry(record.connection).or_default();
        match &record.event {
            Event::Connection { host, port } => {
                connection.host.clone_from(host);
                connection.port = *port;
            }
            Event::Opened { banner } => {
                connection.banner.get_or_insert(*banner);
            }
            Event::Closed { .. } => {}
            Event::Message {
                direction,
                header,
                body,
            } => {
                if self.messages == 0 {
                    self.first_ns = record.time_ns;
                }
                self.messages += 1;
                self.last_ns = self.last_ns.max(record.time_ns);
                let key = (header.addr.interf, header.addr.index);
                let asked = (key.0, key.1, header.subtype);
                match (direction, header.msg_type) {
                    (Direction::ServerToClient, MsgType::Data) => {
                        *connection.data.entry(key).or_default() += 1;
                        connection.devices.entry(key).or_default();
                    }
                    (Direction::ClientToServer, MsgType::Req) if key.0 != Interface::PLAYER => {
                        connection.asked.insert(asked, body.clone());
                    }
                    (Direction::ServerToClient, MsgType::Ack | MsgType::Nack) => {
                        if key.0 == Interface::PLAYER {
                            learn_devices(connection, Message::decode(*header, body.clone()));
                        } else if let Some(request) = connection.asked.remove(&asked) {
                            let reply = (header.msg_type, body.clone());
                            connection
                                .replies
                                .insert((key.0, key.1, asked.2, request), reply);
                        }
                    }
                    _ => {}
                }
            }
        }
    }
}

/// Takes devices and driver names from the server's `player`-interface replies.
fn learn_devices(connection: &mut ConnectionIndex, reply: Result<Message, crate::DecodeError>) {
    let Ok(reply) = reply else { return };
    if reply.header.msg_type != MsgType::Ack {
        return;
    }
    match (reply.header.subtype, reply.body) {
        (player::REQ_DEVLIST, Body::Player(Player::DevList(list))) => {
            for addr in list.devices {
                connection
                    .devices
                    .entry((addr.interf, addr.index))
                    .or_default();
            }
        }
        (player::REQ_DRIVERINFO, Body::Player(Player::DriverInfo(info))) => {
            let name = info.driver_name.as_str().into_owned();
            connection
                .devices
                .insert((info.addr.interf, info.addr.index), name);
        }
        _ => {}
    }
}

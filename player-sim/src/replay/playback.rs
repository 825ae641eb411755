//! The playback thread: reads the recording in order and publishes each recorded DATA message
//! on its robot's port when the clock says it is due; on a seek, reads again from the nearest
//! seek point and publishes the newest message of each device before the new position, so a
//! client shows the robots as they were there.

use std::collections::{BTreeMap, HashMap};
use std::sync::Arc;
use std::time::{Duration, Instant};

use player_proto::capture::Direction;
use player_proto::interfaces::log::{self, Log};
use player_proto::message::Body;
use player_proto::recording::index::SeekPoint;
use player_proto::recording::{Event, Record, RecordSource, RecordStream};
use player_proto::server::Publisher;
use player_proto::wire::{DevAddr, Header, Interface, MsgType};

use super::clock::{Clock, Wake};

/// How often the `log` devices report where playback is.
pub const STATUS_EVERY: Duration = Duration::from_millis(100);

/// A recorded DATA message, ready to publish.
struct Due {
    at: u64,
    port: u16,
    header: Header,
    body: bytes::Bytes,
}

/// Everything the thread needs.
pub struct Playback {
    pub source: Arc<dyn RecordSource>,
    pub clock: Arc<Clock>,
    pub publisher: Publisher,
    /// Served port of each recorded connection.
    pub ports: HashMap<u32, u16>,
    /// The `log` device of each served port.
    pub log_devices: Vec<DevAddr>,
    pub seek_points: Vec<SeekPoint>,
    /// Time of the first message: positions count from it.
    pub first_ns: u64,
    /// Start again at the end instead of pausing there.
    pub looping: bool,
}

type Reader = Box<dyn RecordStream>;

impl Playback {
    pub fn run(self) {
        // From the clock's first count, not the count now: a seek asked before this thread ran
        // is one still to make (read as done, every message up to it was published).
        let mut seeks = Clock::SEEKS_AT_START;
        let mut changes = 0;
        let mut reader = self.open_at(self.seek_points.first().copied());
        let mut next: Option<Due> = None;
        let mut reported = Instant::now();
        let mut at_end = false;
        self.report();
        loop {
            if next.is_none() {
                next = reader.as_mut().and_then(|r| self.next_due(r));
            }
            let Some(due) = &next else {
                if !std::mem::replace(&mut at_end, true) {
                    if self.looping && self.clock.duration_ns() > 0 {
                        self.clock.seek(0);
                    } else {
                        self.clock.reached_end();
                    }
                }
                // Wait for a seek (or a stop) with nothing due.
                match self
                    .clock
                    .wait_for(u64::MAX, seeks, &mut changes, STATUS_EVERY)
                {
                    Wake::Stop => return,
                    Wake::Seek { to, seeks: now } => {
                        seeks = now;
                        (reader, next) = self.seek(to);
                        at_end = false;
                    }
                    Wake::Due | Wake::Changed => {}
                }
                self.report();
                continue;
            };
            match self
                .clock
                .wait_for(due.at, seeks, &mut changes, STATUS_EVERY)
            {
                Wake::Stop => return,
                Wake::Due => {
                    self.publish(due);
                    next = None;
                }
                Wake::Seek { to, seeks: now } => {
                    seeks = now;
                    (reader, next) = self.seek(to);
                    self.report();
                    reported = Instant::now();
                }
                Wake::Changed => {
                    self.report();
                    reported = Instant::now();
                }
            }
            if reported.elapsed() >= STATUS_EVERY {
                self.report();
                reported = Instant::now();
            }
        }
    }

    /// A reader at `point`, or `None` (logged) if the file cannot be read there.
    fn open_at(&self, point: Option<SeekPoint>) -> Option<Reader> {
        match self.source.read_from(point?) {
            Ok(reader) => Some(reader),
            Err(e) => {
                tracing::error!("cannot read {} again: {e}", self.source.name());
                None
            }
        }
    }

    /// The next recorded DATA message from a server; `None` at the end (a torn or damaged
    /// tail is logged: playback ends there).
    fn next_due(&self, reader: &mut Reader) -> Option<Due> {
        loop {
            let record = match reader.next_record() {
                Ok(Some(record)) => record,
                Ok(None) => return None,
                Err(e) => {
                    tracing::warn!("playback ends early: {e}");
                    return None;
                }
            };
            if let Some(due) = self.due(record) {
                return Some(due);
            }
        }
    }

    fn due(&self, record: Record) -> Option<Due> {
        let Event::Message {
            direction: Direction::ServerToClient,
            header,
            body,
        } = record.event
        else {
            return None;
        };
        if header.msg_type != MsgType::Data {
            return None;
        }
        Some(Due {
            at: record.time_ns.saturating_sub(self.first_ns),
            port: *self.ports.get(&record.connection)?,
            header,
            body,
        })
    }

    /// Reads from the seek point before `to`, keeping the newest message of each device and
    /// subtype up to `to`, publishes those, and returns the reader after them with the first
    /// message past `to`, which is due next.
    fn seek(&self, to: u64) -> (Option<Reader>, Option<Due>) {
        let target = self.first_ns.saturating_add(to);
        let after = self.seek_points.partition_point(|p| p.time_ns <= target);
        let point = self.seek_points.get(after.saturating_sub(1)).copied();
        let Some(mut reader) = self.open_at(point) else {
            return (None, None);
        };
        let mut newest: BTreeMap<(u16, Interface, u16, u8), Due> = BTreeMap::new();
        let mut next = None;
        while let Some(due) = self.next_due(&mut reader) {
            if due.at > to {
                next = Some(due);
                break;
            }
            let h = &due.header;
            newest.insert((due.port, h.addr.interf, h.addr.index, h.subtype), due);
        }
        for due in newest.values() {
            self.publish(due);
        }
        (Some(reader), next)
    }

    fn publish(&self, due: &Due) {
        let h = &due.header;
        let addr = DevAddr {
            host: 0,
            robot: u32::from(due.port),
            interf: h.addr.interf,
            index: h.addr.index,
        };
        self.publisher.publish(
            addr,
            h.subtype,
            Body::Unknown(due.body.clone()),
            h.timestamp,
        );
    }

    /// Tells the `log` devices' subscribers where playback is.
    fn report(&self) {
        let playback = Body::Log(Log::Playback(self.clock.playback()));
        let now = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0.0, |d| d.as_secs_f64());
        for &addr in &self.log_devices {
            if self.publisher.subscribers(addr) > 0 {
                self.publisher
                    .publish(addr, log::DATA_PLAYBACK, playback.clone(), now);
            }
        }
    }
}

//! The simulation's own recording: every served robot seen as by a client subscribed to all
//! of its devices, stamped with simulated time. Unlike a recording made by a client (stamped
//! when each message arrived), it depends only on the world, the seed and the commands, so a
//! lockstep run is the same file, byte for byte, on an idle or a loaded machine.
//!
//! It goes through a recorder's [`ConnectionOpener`] — a `.prec` or MCAP recorder's — one
//! connection per served port, declared in port order at simulated time 0.

use std::sync::{Arc, Mutex};
use std::time::{Duration, SystemTime, UNIX_EPOCH};

use player_proto::capture::Direction;
use player_proto::client::{ConnectionTap, TapEvent};
use player_proto::message::{Body, Message};
use player_proto::recording::{ConnectionOpener, Recorder};
use player_proto::wire::{Banner, DevAddr, HEADER_LEN, Header, MsgType};

/// Where a simulation's recording goes ([`crate::serve::ServeOptions::record`]).
#[derive(Clone)]
pub struct SimRecording(pub ConnectionOpener);

impl SimRecording {
    /// Records through `recorder` (finish it after the simulation stops).
    pub fn to(recorder: &Recorder) -> SimRecording {
        SimRecording(recorder.opener())
    }
}

impl std::fmt::Debug for SimRecording {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("SimRecording")
    }
}

/// Simulated seconds as the recording's clock: the Unix epoch plus the simulated time.
pub fn sim_clock(time: f64) -> SystemTime {
    UNIX_EPOCH + Duration::from_secs_f64(time.max(0.0))
}

/// One served port's connection in the recording.
#[derive(Clone)]
pub struct PortRecord {
    tap: ConnectionTap,
    /// Messages of one step are written in the order they are given, under this lock, so a
    /// command recorded by a session's thread never lands inside a step's batch.
    order: Arc<Mutex<()>>,
}

impl PortRecord {
    /// Declares the connection of `port` (as configured) and its banner.
    pub fn open(recording: &SimRecording, host: &str, port: u16, order: Arc<Mutex<()>>) -> Self {
        let tap = (recording.0)(host, port, sim_clock(0.0));
        if let Ok(banner) = Banner::new(
            player_proto::server::ServerConfig::default()
                .version
                .as_str(),
        ) {
            tap(sim_clock(0.0), TapEvent::Opened(&banner));
        }
        PortRecord { tap, order }
    }

    /// Records `body` as the message `addr` sent (data) or was sent (a command), at `time`.
    pub fn message(
        &self,
        time: f64,
        direction: Direction,
        addr: DevAddr,
        msg_type: MsgType,
        subtype: u8,
        body: &Body,
    ) {
        let message = Message::new(addr, msg_type, subtype, body.clone()).at(time);
        self.raw(time, direction, &message);
    }

    /// Records a message already made.
    pub fn raw(&self, time: f64, direction: Direction, message: &Message) {
        let bytes = message.to_bytes();
        let body = bytes.slice(HEADER_LEN..);
        let header = Header {
            size: u32::try_from(body.len()).unwrap_or(u32::MAX),
            ..message.header
        };
        let _order = self.order.lock().unwrap_or_else(|e| e.into_inner());
        (self.tap)(
            sim_clock(time),
            TapEvent::Frame {
                direction,
                header: &header,
                body: &body,
            },
        );
    }
}

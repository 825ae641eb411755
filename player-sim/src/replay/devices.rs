//! What a replay serves on each port: the recorded devices, which answer a request only as
//! the robot answered that very request and refuse commands, and a `log` device that controls
//! playback.

use std::collections::HashMap;
use std::sync::Arc;

use bytes::{Bytes, BytesMut};
use player_proto::interfaces::log::{self, Log, LogState};
use player_proto::message::{Body, Message};
use player_proto::recording::index::RequestKey;
use player_proto::server::{Device, Reply};
use player_proto::wire::MsgType;

use super::clock::Clock;

/// The recorded replies of one robot, by the request they answered.
pub type Replies = Arc<HashMap<RequestKey, (MsgType, Bytes)>>;

/// A device of the recording.
pub struct ReplayedDevice {
    pub driver: String,
    pub replies: Replies,
}

impl Device for ReplayedDevice {
    fn driver_name(&self) -> &str {
        &self.driver
    }

    /// Answers as recorded when this exact request (device, subtype, body bytes) was asked
    /// during the recording; anything else could only be guessed, so it is refused.
    fn on_request(&mut self, request: &Message) -> Reply {
        let mut body = BytesMut::with_capacity(request.body_len());
        request.body.encode(&mut body);
        body.extend_from_slice(&request.trailing);
        let h = &request.header;
        let key = (h.addr.interf, h.addr.index, h.subtype, body.freeze());
        match self.replies.get(&key) {
            Some((MsgType::Ack, reply)) => Reply::Ack(Body::Unknown(reply.clone())),
            Some(_) => Reply::Nack,
            None => {
                tracing::info!("refused {}: not asked during the recording", request.header);
                Reply::Nack
            }
        }
    }

    /// A recording cannot be steered.
    fn accepts_commands(&self) -> bool {
        false
    }
}

/// The `log` device of a replay: Player's read-state, rewind and state requests, and the
/// speed, seek and step extension (`player_proto::interfaces::log`).
pub struct LogDevice {
    pub clock: Arc<Clock>,
}

const NS_PER_S: f64 = 1e9;

/// Seconds of recording in the clock's unit; `None` for a negative or non-finite value.
fn to_ns(seconds: f64) -> Option<u64> {
    (seconds >= 0.0 && seconds.is_finite()).then_some((seconds * NS_PER_S) as u64)
}

impl Device for LogDevice {
    fn driver_name(&self) -> &str {
        "readlog"
    }

    fn on_request(&mut self, request: &Message) -> Reply {
        let done = Reply::Ack(Body::Empty);
        match (request.header.subtype, &request.body) {
            (log::REQ_SET_READ_STATE, Body::Log(Log::SetReadState(s))) => {
                self.clock.set_playing(s.state != 0);
                done
            }
            (log::REQ_GET_STATE, _) => Reply::Ack(Body::Log(Log::State(LogState {
                kind: log::TYPE_READ,
                state: u8::from(self.clock.is_playing()),
            }))),
            (log::REQ_SET_READ_REWIND, _) => {
                self.clock.seek(0);
                done
            }
            (log::REQ_SET_READ_SPEED, Body::Log(Log::SetReadSpeed(s))) => {
                if self.clock.set_speed(s.speed) {
                    done
                } else {
                    Reply::Nack
                }
            }
            (log::REQ_SET_READ_POSITION, Body::Log(Log::SetReadPosition(p))) => {
                match to_ns(p.position) {
                    Some(at) => {
                        self.clock.seek(at);
                        done
                    }
                    None => Reply::Nack,
                }
            }
            (log::REQ_READ_STEP, Body::Log(Log::ReadStep(s))) => match to_ns(s.seconds) {
                Some(by) => {
                    self.clock.step(by);
                    done
                }
                None => Reply::Nack,
            },
            // A read device has nothing to write.
            _ => Reply::Nack,
        }
    }

    fn accepts_commands(&self) -> bool {
        false
    }
}

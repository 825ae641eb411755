//! An in-memory device for tests and demos: data is pushed in, commands and requests are
//! recorded, requests are answered from a table or later by hand.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use player_proto::interfaces::kind::MessageKind;
use player_proto::message::{Body, Message};

use super::{ConnectionState, DeviceAccess, PendingReply, RequestError, Responder, Stamped};

/// What a request came to: the ACK message, or why there is none.
pub type ReplyOutcome = Result<Message, RequestError>;

#[derive(Default)]
pub struct RecordingDevice {
    pub data: Mutex<Vec<Stamped>>,
    pub commands: Mutex<Vec<Body>>,
    pub requests: Mutex<Vec<(MessageKind, Body)>>,
    /// Answers given at once to requests of a kind.
    pub replies: Mutex<Vec<(MessageKind, ReplyOutcome)>>,
    /// Requests the table had no reply for, still waiting: [`RecordingDevice::answer_later`]
    /// answers them, as a server that replies late.
    pub pending: Mutex<Vec<(MessageKind, Responder)>>,
    /// `None` reads as connected.
    pub state: Mutex<Option<ConnectionState>>,
    pushed: AtomicU64,
}

impl RecordingDevice {
    /// Makes `message` the newest data of its subtype.
    pub fn push(&self, message: Message) {
        let mut data = self.data.lock().expect("data");
        let subtype = message.header.subtype;
        let seq = self.pushed.fetch_add(1, Ordering::Relaxed) + 1;
        data.retain(|s| s.message.header.subtype != subtype);
        data.push(Stamped {
            server_time: message.header.timestamp,
            message: Arc::new(message),
            received: Instant::now(),
            seq,
        });
    }

    /// Answers every later request of `kind` at once with `outcome`.
    pub fn reply_to(&self, kind: MessageKind, outcome: ReplyOutcome) {
        self.replies.lock().expect("replies").push((kind, outcome));
    }

    /// Answers the waiting requests of `kind`; returns how many there were.
    pub fn answer_later(&self, kind: MessageKind, outcome: ReplyOutcome) -> usize {
        let mut pending = self.pending.lock().expect("pending");
        let before = pending.len();
        pending.retain(|(k, responder)| {
            if *k == kind {
                responder.answer(outcome.clone());
            }
            *k != kind
        });
        before - pending.len()
    }
}

impl DeviceAccess for RecordingDevice {
    fn latest(&self, kind: MessageKind) -> Option<Stamped> {
        self.data
            .lock()
            .expect("data")
            .iter()
            .find(|s| s.message.header.subtype == kind.subtype)
            .cloned()
    }

    fn command(&self, body: Body) {
        self.commands.lock().expect("commands").push(body);
    }

    fn request(&self, kind: MessageKind, body: Body) -> PendingReply {
        self.requests.lock().expect("requests").push((kind, body));
        let replies = self.replies.lock().expect("replies");
        if let Some((_, reply)) = replies.iter().find(|(k, _)| *k == kind) {
            return PendingReply::ready(reply.clone());
        }
        let (responder, pending) = PendingReply::channel();
        self.pending
            .lock()
            .expect("pending")
            .push((kind, responder));
        pending
    }

    fn link_state(&self) -> ConnectionState {
        self.state
            .lock()
            .expect("state")
            .clone()
            .unwrap_or(ConnectionState::Connected)
    }
}

//! What a plugin sees of the Player device it was made for: the newest data, commands,
//! requests and the link state. pv3d implements this over the Player client; tests feed known
//! data through a small in-memory implementation.

use std::sync::{Arc, Mutex};
use std::time::Instant;

use player_proto::message::{Body, Message};

/// A data message and how fresh it is.
#[derive(Debug, Clone)]
pub struct Sample {
    pub message: Arc<Message>,
    /// When the client received it.
    pub received: Instant,
    /// Counts messages of this device and subtype; a plugin redraws when it changes.
    pub seq: u64,
}

/// Which sample of one data subtype a plugin took last, so that it acts on each sample once
/// however often it is updated.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct LastTaken {
    seq: Option<u64>,
}

impl LastTaken {
    /// Whether `sample` is another than the one taken last; if so, it is now the one taken.
    pub fn is_new(&mut self, sample: &Sample) -> bool {
        let new = self.seq != Some(sample.seq);
        self.seq = Some(sample.seq);
        new
    }

    /// The device's newest sample of `subtype`, unless it was taken already.
    pub fn newest(&mut self, device: Option<&dyn DeviceAccess>, subtype: u8) -> Option<Sample> {
        device?.latest(subtype).filter(|s| self.is_new(s))
    }

    /// Forgets the sample taken, so that the newest is taken again (to redraw it).
    pub fn forget(&mut self) {
        self.seq = None;
    }
}

/// The state of the connection to the device's server.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LinkState {
    Connecting,
    Connected,
    Reconnecting { attempt: u32 },
    Failed(String),
}

impl LinkState {
    pub fn is_connected(&self) -> bool {
        matches!(self, LinkState::Connected)
    }
}

/// Why a request got no useful reply.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RequestFailure {
    #[error("the device refused the request (NACK)")]
    Nack,
    #[error("no reply within the timeout")]
    Timeout,
    #[error("not connected: {0}")]
    Disconnected(String),
}

/// What a request came to: the ACK message, or why there is none.
pub type ReplyOutcome = Result<Arc<Message>, RequestFailure>;

type Poll = Box<dyn FnMut() -> Option<ReplyOutcome> + Send>;

/// A reply that will arrive later; polled from the UI thread, never waited on.
#[derive(Clone, Default)]
pub struct ReplyTicket {
    filled: Arc<Mutex<Option<ReplyOutcome>>>,
    poll: Option<Arc<Mutex<Poll>>>,
}

impl std::fmt::Debug for ReplyTicket {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("ReplyTicket")
    }
}

impl ReplyTicket {
    /// A ticket whose outcome is found by asking `poll` (e.g. a client's pending reply).
    pub fn polled(poll: impl FnMut() -> Option<ReplyOutcome> + Send + 'static) -> ReplyTicket {
        ReplyTicket {
            filled: Arc::default(),
            poll: Some(Arc::new(Mutex::new(Box::new(poll)))),
        }
    }

    /// Delivers the outcome (called by whoever talks to the server).
    pub fn fulfil(&self, outcome: ReplyOutcome) {
        *self.filled.lock().expect("reply ticket") = Some(outcome);
    }

    /// Takes the outcome if it has arrived.
    pub fn try_take(&self) -> Option<ReplyOutcome> {
        if let Some(outcome) = self.filled.lock().expect("reply ticket").take() {
            return Some(outcome);
        }
        let poll = self.poll.as_ref()?;
        (poll.lock().expect("reply ticket"))()
    }
}

/// Access to one device.
pub trait DeviceAccess: Send + Sync {
    /// The newest DATA message of `subtype` this device sent, if any.
    fn latest(&self, subtype: u8) -> Option<Sample>;
    /// Sends a command (fire and forget). The subtype comes from the typed body.
    fn command(&self, body: Body);
    /// Sends a request; the ticket receives the ACK (or the failure).
    fn request(&self, subtype: u8, body: Body) -> ReplyTicket;
    fn link_state(&self) -> LinkState;
    /// Whether this device is only observed (commands and configuration requests are refused
    /// before they are sent): a plugin then offers no tele-operation.
    fn read_only(&self) -> bool {
        false
    }
}

/// An in-memory device for tests and demos: data is pushed in, commands and requests are
/// recorded, requests are answered from a table.
#[derive(Default)]
pub struct RecordingDevice {
    pub data: Mutex<Vec<Sample>>,
    pub commands: Mutex<Vec<Body>>,
    pub requests: Mutex<Vec<(u8, Body)>>,
    pub replies: Mutex<Vec<(u8, ReplyOutcome)>>,
    /// Requests the table had no reply for, still waiting: [`RecordingDevice::answer_later`]
    /// answers them, as a server that replies late.
    pub pending: Mutex<Vec<(u8, ReplyTicket)>>,
    pub state: Mutex<Option<LinkState>>,
    pushed: std::sync::atomic::AtomicU64,
}

impl RecordingDevice {
    /// Makes `message` the newest data of its subtype.
    pub fn push(&self, message: Message) {
        let mut data = self.data.lock().expect("data");
        let subtype = message.header.subtype;
        let seq = self
            .pushed
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed)
            + 1;
        data.retain(|s| s.message.header.subtype != subtype);
        data.push(Sample {
            message: Arc::new(message),
            received: Instant::now(),
            seq,
        });
    }

    /// Answers the waiting requests of `subtype`; returns how many there were.
    pub fn answer_later(&self, subtype: u8, outcome: ReplyOutcome) -> usize {
        let mut pending = self.pending.lock().expect("pending");
        let before = pending.len();
        pending.retain(|(s, ticket)| {
            if *s == subtype {
                ticket.fulfil(outcome.clone());
            }
            *s != subtype
        });
        before - pending.len()
    }
}

impl DeviceAccess for RecordingDevice {
    fn latest(&self, subtype: u8) -> Option<Sample> {
        self.data
            .lock()
            .expect("data")
            .iter()
            .find(|s| s.message.header.subtype == subtype)
            .cloned()
    }

    fn command(&self, body: Body) {
        self.commands.lock().expect("commands").push(body);
    }

    fn request(&self, subtype: u8, body: Body) -> ReplyTicket {
        self.requests
            .lock()
            .expect("requests")
            .push((subtype, body));
        let ticket = ReplyTicket::default();
        if let Some((_, reply)) = self
            .replies
            .lock()
            .expect("replies")
            .iter()
            .find(|(s, _)| *s == subtype)
        {
            ticket.fulfil(reply.clone());
        } else {
            self.pending
                .lock()
                .expect("pending")
                .push((subtype, ticket.clone()));
        }
        ticket
    }

    fn link_state(&self) -> LinkState {
        self.state
            .lock()
            .expect("state")
            .clone()
            .unwrap_or(LinkState::Connected)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use player_proto::DevAddr;
    use player_proto::interfaces::sonar::{Sonar, SonarData};
    use player_proto::wire::MsgType;

    #[test]
    fn each_sample_is_taken_once_until_forgotten() {
        let device = RecordingDevice::default();
        let mut taken = LastTaken::default();
        assert!(taken.newest(Some(&device), 1).is_none(), "nothing yet");
        let addr: DevAddr = "sonar:0".parse().unwrap();
        let ranges = Sonar::Ranges(SonarData { ranges: vec![1.0] });
        device.push(Message::typed(addr, MsgType::Data, ranges));
        assert!(taken.newest(Some(&device), 1).is_some());
        assert!(
            taken.newest(Some(&device), 1).is_none(),
            "the same sample again"
        );
        taken.forget();
        assert!(
            taken.newest(Some(&device), 1).is_some(),
            "taken again after forget"
        );
        assert!(taken.newest(None, 1).is_none(), "no device, no sample");
    }
}

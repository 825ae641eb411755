//! Requests waiting for their reply: matched by interface, index and subtype (a reply reuses
//! its request's subtype), oldest first, each with a deadline — and the handle's side of one,
//! a [`PendingReply`].

use std::collections::VecDeque;
use std::sync::mpsc;
use std::time::Duration;

use tokio::time::Instant;

use crate::interfaces::player::{self, Player};
use crate::message::{Body, Message};
use crate::wire::{Interface, MsgType};

/// Why a request has no useful reply.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RequestError {
    /// The server answered NACK (with the NACK, whose body may explain).
    #[error("the server refused the request (NACK)")]
    Nack(Box<Message>),
    #[error("no reply within {0:?}")]
    Timeout(Duration),
    #[error("not connected: {0}")]
    Disconnected(String),
    #[error("too many requests in flight ({0}); try again later")]
    TooManyPending(usize),
    #[error("the subscription was refused (access {0})")]
    AccessDenied(u8),
    /// A read-only client was asked to command or configure a device; nothing was sent.
    #[error("read-only client: {0} was not sent")]
    ReadOnly(String),
    /// A command's body has no structure, so its subtype is unknown; nothing was sent.
    #[error("a command to {0} needs a typed body")]
    Untyped(String),
}

/// Where a reply goes. A std channel, so the user-facing side can wait on it from any thread,
/// async or not.
pub(crate) type ReplySender = mpsc::Sender<Result<Message, RequestError>>;

/// A reply that is on its way; poll it from a UI thread, never blocking.
pub struct PendingReply(pub(crate) mpsc::Receiver<Result<Message, RequestError>>);

impl PendingReply {
    /// The outcome if it has arrived.
    pub fn try_get(&self) -> Option<Result<Message, RequestError>> {
        match self.0.try_recv() {
            Ok(outcome) => Some(outcome),
            Err(mpsc::TryRecvError::Empty) => None,
            Err(mpsc::TryRecvError::Disconnected) => Some(Err(thread_ended())),
        }
    }

    /// Waits for the outcome, at most `timeout`.
    pub fn wait(self, timeout: Duration) -> Result<Message, RequestError> {
        match self.0.recv_timeout(timeout) {
            Ok(outcome) => outcome,
            Err(mpsc::RecvTimeoutError::Timeout) => Err(RequestError::Timeout(timeout)),
            Err(mpsc::RecvTimeoutError::Disconnected) => Err(thread_ended()),
        }
    }
}

pub(crate) fn thread_ended() -> RequestError {
    RequestError::Disconnected("the robot thread ended".into())
}

/// Who waits for a reply.
pub(crate) enum Awaiter {
    /// A caller of the handle.
    Caller(ReplySender),
    /// A caller who subscribed to this device: a refusal ends the subscription.
    Subscriber {
        device: (Interface, u16),
        reply: ReplySender,
    },
    /// Nobody (a liveness probe, a PULL round's data request): the reply is only expected, so
    /// that it is not taken for a reply to nothing.
    Nobody,
}

impl Awaiter {
    fn send(self, outcome: Result<Message, RequestError>) {
        // The asker may have given up; that is fine.
        match self {
            Awaiter::Caller(reply) | Awaiter::Subscriber { reply, .. } => {
                let _ = reply.send(outcome);
            }
            Awaiter::Nobody => {}
        }
    }

    /// Fails at once (nothing was sent).
    pub fn fail(self, error: RequestError) {
        self.send(Err(error));
    }
}

/// What became of a reply.
#[derive(Debug)]
pub(crate) enum Resolved {
    /// Handed to its asker.
    Delivered,
    /// Handed to a subscriber; the server granted the subscription or refused it, and the
    /// newest such answer decides whether the device stays subscribed.
    Subscription {
        device: (Interface, u16),
        granted: bool,
    },
    /// Nothing was waiting for it.
    Orphan(Box<Message>),
}

/// Does a device request's reply grant the access asked for?
pub(crate) fn granted(reply: &Message, access: u8) -> bool {
    matches!(&reply.body, Body::Player(Player::Device(d)) if d.access == access)
        && reply.header.msg_type == MsgType::Ack
}

struct Pending {
    key: (Interface, u16, u8),
    deadline: Instant,
    timeout: Duration,
    awaiter: Awaiter,
}

/// The table of requests in flight.
#[derive(Default)]
pub(crate) struct PendingRequests {
    pending: VecDeque<Pending>,
}

impl PendingRequests {
    pub fn len(&self) -> usize {
        self.pending.len()
    }

    /// Expects a reply to `request` within `timeout`.
    pub fn add(&mut self, request: &Message, timeout: Duration, awaiter: Awaiter) {
        let h = request.header;
        self.pending.push_back(Pending {
            key: (h.addr.interf, h.addr.index, h.subtype),
            deadline: Instant::now() + timeout,
            timeout,
            awaiter,
        });
    }

    /// Hands a reply to the oldest request it answers.
    pub fn resolve(&mut self, reply: Message) -> Resolved {
        let h = reply.header;
        let key = (h.addr.interf, h.addr.index, h.subtype);
        let Some(i) = self.pending.iter().position(|p| p.key == key) else {
            return Resolved::Orphan(Box::new(reply));
        };
        let pending = self.pending.remove(i).expect("index found above");
        let resolved = match &pending.awaiter {
            Awaiter::Subscriber { device, .. } => Resolved::Subscription {
                device: *device,
                granted: granted(&reply, player::OPEN_MODE),
            },
            _ => Resolved::Delivered,
        };
        pending.awaiter.send(match h.msg_type {
            MsgType::Ack => Ok(reply),
            _ => Err(RequestError::Nack(Box::new(reply))),
        });
        resolved
    }

    /// The earliest deadline, to sleep until.
    pub fn next_deadline(&self) -> Option<Instant> {
        self.pending.iter().map(|p| p.deadline).min()
    }

    /// Fails every request whose deadline has passed.
    pub fn expire(&mut self, now: Instant) {
        let mut kept = VecDeque::with_capacity(self.pending.len());
        for p in self.pending.drain(..) {
            if p.deadline <= now {
                p.awaiter.fail(RequestError::Timeout(p.timeout));
            } else {
                kept.push_back(p);
            }
        }
        self.pending = kept;
    }

    /// Fails every request (the connection dropped).
    pub fn fail_all(&mut self, why: &str) {
        for p in self.pending.drain(..) {
            p.awaiter.fail(RequestError::Disconnected(why.to_string()));
        }
    }
}

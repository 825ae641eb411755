//! Requests waiting for their reply: matched by interface, index and subtype (a reply reuses
//! its request's subtype), oldest first, each with a deadline.

use std::collections::VecDeque;

use tokio::time::Instant;

use crate::message::Message;
use crate::wire::{Interface, MsgType};

/// Why a request has no useful reply.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RequestError {
    /// The server answered NACK (with the NACK, whose body may explain).
    #[error("the server refused the request (NACK)")]
    Nack(Box<Message>),
    #[error("no reply within {0:?}")]
    Timeout(std::time::Duration),
    #[error("not connected: {0}")]
    Disconnected(String),
    #[error("too many requests in flight ({0}); try again later")]
    TooManyPending(usize),
    #[error("the subscription was refused (access {0})")]
    AccessDenied(u8),
}

/// Where a reply goes. A std channel, so the user-facing side can wait on it from any thread,
/// async or not.
pub(crate) type ReplySender = std::sync::mpsc::Sender<Result<Message, RequestError>>;

struct Pending {
    key: (Interface, u16, u8),
    deadline: Instant,
    timeout: std::time::Duration,
    reply: ReplySender,
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

    pub fn add(
        &mut self,
        key: (Interface, u16, u8),
        timeout: std::time::Duration,
        reply: ReplySender,
    ) {
        self.pending.push_back(Pending {
            key,
            deadline: Instant::now() + timeout,
            timeout,
            reply,
        });
    }

    /// Hands a reply to the oldest request it answers. Returns the reply back when nothing was
    /// waiting for it (a reply to nothing).
    pub fn resolve(&mut self, reply: Message) -> Option<Message> {
        let h = reply.header;
        let key = (h.addr.interf, h.addr.index, h.subtype);
        let Some(i) = self.pending.iter().position(|p| p.key == key) else {
            return Some(reply);
        };
        let pending = self.pending.remove(i).expect("index found above");
        let outcome = match h.msg_type {
            MsgType::Ack => Ok(reply),
            _ => Err(RequestError::Nack(Box::new(reply))),
        };
        // The asker may have given up; that is fine.
        let _ = pending.reply.send(outcome);
        None
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
                let _ = p.reply.send(Err(RequestError::Timeout(p.timeout)));
            } else {
                kept.push_back(p);
            }
        }
        self.pending = kept;
    }

    /// Fails every request (the connection dropped).
    pub fn fail_all(&mut self, why: &str) {
        for p in self.pending.drain(..) {
            let _ = p
                .reply
                .send(Err(RequestError::Disconnected(why.to_string())));
        }
    }
}

//! The answering end of a [`PendingReply`], for code that answers a request itself rather
//! than through the robot thread: an in-memory test device, a device that refuses at once.

use std::sync::mpsc;

use super::{PendingReply, RequestError};
use crate::message::Message;

/// Delivers the outcome of one request to its [`PendingReply`].
#[derive(Debug, Clone)]
pub struct Responder(mpsc::Sender<Result<Message, RequestError>>);

impl Responder {
    /// Delivers the outcome; nothing happens when the waiting side was dropped.
    pub fn answer(&self, outcome: Result<Message, RequestError>) {
        let _ = self.0.send(outcome);
    }
}

impl PendingReply {
    /// A reply that arrives when the [`Responder`] answers (dropping the responder unanswered
    /// reads as a disconnection).
    pub fn channel() -> (Responder, PendingReply) {
        let (sender, receiver) = mpsc::channel();
        (Responder(sender), PendingReply(receiver))
    }

    /// A reply that is already there.
    pub fn ready(outcome: Result<Message, RequestError>) -> PendingReply {
        let (responder, pending) = PendingReply::channel();
        responder.answer(outcome);
        pending
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reply_arrives_when_answered_and_not_before() {
        let (responder, pending) = PendingReply::channel();
        assert!(pending.try_get().is_none());
        responder.answer(Err(RequestError::TooManyPending(3)));
        assert_eq!(
            pending.try_get(),
            Some(Err(RequestError::TooManyPending(3)))
        );
    }

    #[test]
    fn an_unanswered_responder_dropped_is_a_disconnection() {
        let (responder, pending) = PendingReply::channel();
        drop(responder);
        assert!(matches!(
            pending.try_get(),
            Some(Err(RequestError::Disconnected(_)))
        ));
    }
}

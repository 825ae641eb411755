//! A connection's outgoing queue, with the Player 3 server's rules: PUSH sends at once; PULL
//! holds DATA until the client asks (ACK first, then the data, then SYNCH); replace rules
//! decide what is queued, replaced or ignored; at most 1024 accepted messages wait, the rest
//! are dropped and counted.

use std::collections::VecDeque;
use std::sync::Arc;

use crate::delivery::{DataMode, ReplaceAction, ReplaceRule, ReplaceRules};
use crate::interfaces::common::U32Value;
use crate::interfaces::player::{Player, REQ_DATA, SYNCH_OK, SYNCH_OVERFLOW};
use crate::message::{Body, Message};
use crate::wire::{DevAddr, Interface, MsgType};

/// `PLAYER_MSGQUEUE_DEFAULT_MAXLEN`.
pub const QUEUE_LIMIT: usize = 1024;

/// The outgoing queue of one connection.
#[derive(Debug)]
pub struct OutQueue {
    mode: DataMode,
    rules: ReplaceRules,
    queue: VecDeque<Arc<Message>>,
    /// Messages dropped since the last SYNCH.
    dropped: u32,
    /// A PULL round was asked for and has not ended with a SYNCH yet.
    round_open: bool,
    delivered_in_round: bool,
}

impl Default for OutQueue {
    fn default() -> Self {
        OutQueue {
            mode: DataMode::Push,
            rules: ReplaceRules::default(),
            queue: VecDeque::new(),
            dropped: 0,
            round_open: false,
            delivered_in_round: false,
        }
    }
}

impl OutQueue {
    pub fn mode(&self) -> DataMode {
        self.mode
    }

    pub fn set_mode(&mut self, mode: DataMode) {
        self.mode = mode;
    }

    /// Adds a rule; a rule with the same filters as an existing one only changes its action.
    pub fn add_rule(&mut self, rule: ReplaceRule) {
        self.rules.add(rule);
    }

    pub fn len(&self) -> usize {
        self.queue.len()
    }

    pub fn is_empty(&self) -> bool {
        self.queue.is_empty()
    }

    pub fn dropped(&self) -> u32 {
        self.dropped
    }

    /// Queues a message for the client, applying the replace rules and the length limit.
    pub fn push(&mut self, message: Arc<Message>) {
        let kind = message.header.msg_type;
        let action = self.rules.action_for(&message.header);
        let droppable = matches!(kind, MsgType::Data | MsgType::Cmd);
        match action {
            ReplaceAction::Ignore => {}
            ReplaceAction::Replace => {
                let h = message.header;
                let same = self.queue.iter().rposition(|q| {
                    q.header.msg_type == h.msg_type
                        && q.header.subtype == h.subtype
                        && q.header.addr.same_device(&h.addr)
                });
                match same {
                    Some(i) => self.queue[i] = message,
                    None => self.queue.push_back(message),
                }
            }
            ReplaceAction::Accept if droppable && self.queue.len() >= QUEUE_LIMIT => {
                self.dropped = self.dropped.saturating_add(1);
            }
            ReplaceAction::Accept => self.queue.push_back(message),
        }
    }

    /// The client sent a data request (PULL): its ACK goes to the front of the queue and a
    /// round opens.
    pub fn request_data(&mut self, ack: Arc<Message>) {
        self.queue.push_front(ack);
        if self.mode == DataMode::Pull {
            self.round_open = true;
            self.delivered_in_round = false;
        }
    }

    /// Takes what may be written to the socket now, in order.
    pub fn take_sendable(&mut self) -> Vec<Arc<Message>> {
        match self.mode {
            DataMode::Push => self.queue.drain(..).collect(),
            DataMode::Pull if self.round_open => {
                let out: Vec<Arc<Message>> = self.queue.drain(..).collect();
                if out.iter().any(|m| m.header.msg_type == MsgType::Data) {
                    self.delivered_in_round = true;
                }
                let mut out = out;
                if self.delivered_in_round {
                    out.push(Arc::new(self.synch()));
                    self.round_open = false;
                    self.delivered_in_round = false;
                }
                out
            }
            DataMode::Pull => {
                // Outside a round, replies go out at once, with any older data before them.
                match self
                    .queue
                    .iter()
                    .rposition(|m| m.header.msg_type.is_reply())
                {
                    Some(last_reply) => self.queue.drain(..=last_reply).collect(),
                    None => Vec::new(),
                }
            }
        }
    }

    fn synch(&mut self) -> Message {
        // The real server leaves host, robot and timestamp of SYNCH uninitialised; we send 0.
        let addr = DevAddr::local(Interface::PLAYER, 0);
        let dropped = std::mem::take(&mut self.dropped);
        if dropped > 0 {
            Message::new(
                addr,
                MsgType::Synch,
                SYNCH_OVERFLOW,
                Body::Player(Player::SynchOverflow(U32Value { value: dropped })),
            )
        } else {
            Message::new(addr, MsgType::Synch, SYNCH_OK, Body::Empty)
        }
    }
}

/// The empty ACK of a data request.
pub fn data_request_ack(server_host: u32, port: u32) -> Message {
    let addr = DevAddr {
        host: server_host,
        robot: port,
        interf: Interface::PLAYER,
        index: 0,
    };
    Message::new(addr, MsgType::Ack, REQ_DATA, Body::Empty)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn data(index: u16, subtype: u8) -> Arc<Message> {
        Arc::new(Message::new(
            DevAddr::local(Interface::LASER, index),
            MsgType::Data,
            subtype,
            Body::Empty,
        ))
    }

    fn kinds(messages: &[Arc<Message>]) -> Vec<(MsgType, u8)> {
        messages
            .iter()
            .map(|m| (m.header.msg_type, m.header.subtype))
            .collect()
    }

    #[test]
    fn push_mode_sends_everything_at_once() {
        let mut q = OutQueue::default();
        q.push(data(0, 1));
        q.push(data(0, 1));
        assert_eq!(q.take_sendable().len(), 2);
        assert!(q.is_empty());
    }

    #[test]
    fn pull_rounds_are_ack_data_synch_and_wait_for_data() {
        let mut q = OutQueue::default();
        q.set_mode(DataMode::Pull);
        q.push(data(0, 1));
        assert!(q.take_sendable().is_empty(), "data waits for a request");
        q.request_data(Arc::new(data_request_ack(0, 6665)));
        let round = q.take_sendable();
        assert_eq!(
            kinds(&round),
            [(MsgType::Ack, 4), (MsgType::Data, 1), (MsgType::Synch, 1)]
        );

        // A round with nothing queued: only the ACK, then data and SYNCH when data comes.
        q.request_data(Arc::new(data_request_ack(0, 6665)));
        assert_eq!(kinds(&q.take_sendable()), [(MsgType::Ack, 4)]);
        q.push(data(0, 1));
        assert_eq!(
            kinds(&q.take_sendable()),
            [(MsgType::Data, 1), (MsgType::Synch, 1)]
        );
        assert!(q.take_sendable().is_empty());
    }

    #[test]
    fn replace_keeps_the_newest_and_ignore_drops() {
        let mut q = OutQueue::default();
        q.set_mode(DataMode::Pull);
        q.add_rule(ReplaceRule::newest_data());
        for _ in 0..5 {
            q.push(data(0, 1));
        }
        q.push(data(1, 1));
        assert_eq!(q.len(), 2, "one per device and subtype");
        q.add_rule(ReplaceRule::device_data(
            Interface::LASER,
            1,
            ReplaceAction::Ignore,
        ));
        // The first matching rule decides: the wildcard REPLACE still wins for laser:1.
        q.push(data(1, 1));
        assert_eq!(q.len(), 2);
        let mut q = OutQueue::default();
        q.add_rule(ReplaceRule {
            interf: Some(Interface::LASER),
            index: None,
            msg_type: None,
            subtype: None,
            action: ReplaceAction::Ignore,
        });
        q.push(data(0, 1));
        assert!(q.is_empty());
    }

    #[test]
    fn overflow_is_counted_and_reported_in_the_synch() {
        let mut q = OutQueue::default();
        q.set_mode(DataMode::Pull);
        for _ in 0..QUEUE_LIMIT + 10 {
            q.push(data(0, 1));
        }
        assert_eq!((q.len(), q.dropped()), (QUEUE_LIMIT, 10));
        q.request_data(Arc::new(data_request_ack(0, 6665)));
        let round = q.take_sendable();
        let last = round.last().unwrap();
        assert_eq!(
            (last.header.msg_type, last.header.subtype),
            (MsgType::Synch, SYNCH_OVERFLOW)
        );
        assert_eq!(
            last.body,
            Body::Player(Player::SynchOverflow(U32Value { value: 10 }))
        );
    }

    #[test]
    fn pull_replies_go_out_with_older_data_before_them() {
        let mut q = OutQueue::default();
        q.set_mode(DataMode::Pull);
        q.push(data(0, 1));
        q.push(Arc::new(Message::new(
            DevAddr::local(Interface::LASER, 0),
            MsgType::Ack,
            1,
            Body::Empty,
        )));
        q.push(data(0, 1));
        assert_eq!(
            kinds(&q.take_sendable()),
            [(MsgType::Data, 1), (MsgType::Ack, 1)]
        );
        assert_eq!(q.len(), 1);
    }
}

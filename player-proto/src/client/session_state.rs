//! The session as the robot thread keeps it — subscriptions, data mode, replace rules — which
//! it alone changes (on the handle's commands) and replays after every reconnect.

use std::collections::BTreeSet;
use std::sync::Arc;

use super::commands::{Command, PullWaiter};
use super::options::ClientOptions;
use super::published::Board;
use super::requests::Awaiter;
use super::store::DataStore;
use crate::delivery::{DataMode, ReplaceRule, ReplaceRules};
use crate::interfaces::player::{self, DeviceReq, Player};
use crate::message::{Body, Message};
use crate::wire::{DevAddr, Interface, MsgType, PlayerString};

/// What a command needs sent, once the session state has taken it in.
pub(crate) enum Outgoing {
    Send(Message),
    Request { message: Message, awaiter: Awaiter },
    Pull(PullWaiter),
    Shutdown,
}

pub(crate) struct SessionState {
    /// Ordered, so that a reconnect restores them in a predictable order.
    subscriptions: BTreeSet<(Interface, u16)>,
    data_mode: DataMode,
    rules: ReplaceRules,
    /// Where the data mode and rules are shown to the handle.
    board: Arc<Board>,
}

/// A request to the server itself (the `player` interface).
pub(crate) fn to_server(subtype: u8, body: Body) -> Message {
    Message::new(
        DevAddr::local(Interface::PLAYER, 0),
        MsgType::Req,
        subtype,
        body,
    )
}

/// Opens or closes a device.
pub(crate) fn device_request((interf, index): (Interface, u16), access: u8) -> Message {
    let req = DeviceReq {
        addr: DevAddr::local(interf, index),
        access,
        driver_name: PlayerString::default(),
    };
    to_server(player::REQ_DEV, Body::Player(Player::Device(req)))
}

impl SessionState {
    /// The session the connect-time options ask for.
    pub fn new(options: &ClientOptions, board: Arc<Board>) -> SessionState {
        let mut rules = ReplaceRules::default();
        if options.replace_old_data {
            rules.add(ReplaceRule::newest_data());
        }
        let session = SessionState {
            subscriptions: BTreeSet::new(),
            data_mode: options.data_mode,
            rules,
            board,
        };
        session.publish();
        session
    }

    fn publish(&self) {
        let (mode, rules) = (self.data_mode, self.rules.as_slice().to_vec());
        self.board.publish(|s| {
            s.data_mode = mode;
            s.replace_rules = rules;
        });
    }

    pub fn is_subscribed(&self, interf: Interface, index: u16) -> bool {
        self.subscriptions.contains(&(interf, index))
    }

    /// Ends a subscription and forgets its data.
    fn unsubscribe(&mut self, device: (Interface, u16), store: &DataStore) {
        self.subscriptions.remove(&device);
        store.forget(device.0, device.1);
    }

    /// The server answered a subscription: a refusal ends it (it would only be refused again
    /// after every reconnect), a grant (re)establishes it.
    pub fn settle_subscription(
        &mut self,
        device: (Interface, u16),
        granted: bool,
        store: &DataStore,
    ) {
        if granted {
            self.subscriptions.insert(device);
        } else {
            self.unsubscribe(device, store);
        }
    }

    /// Takes a command's change into the session and says what must go out. The change holds
    /// whether or not the server is there to hear it now: it is replayed on the next connection.
    pub fn apply(&mut self, command: Command, store: &DataStore) -> Outgoing {
        match command {
            Command::Request { message, reply } => Outgoing::Request {
                message,
                awaiter: Awaiter::Caller(reply),
            },
            Command::Send(message) => Outgoing::Send(message),
            Command::Subscribe { device, reply } => {
                self.subscriptions.insert(device);
                Outgoing::Request {
                    message: device_request(device, player::OPEN_MODE),
                    awaiter: Awaiter::Subscriber { device, reply },
                }
            }
            Command::Unsubscribe { device, reply } => {
                self.unsubscribe(device, store);
                Outgoing::Request {
                    message: device_request(device, player::CLOSE_MODE),
                    awaiter: Awaiter::Caller(reply),
                }
            }
            Command::SetDataMode { mode, reply } => {
                self.data_mode = mode;
                self.publish();
                Outgoing::Request {
                    message: data_mode_request(mode),
                    awaiter: Awaiter::Caller(reply),
                }
            }
            Command::AddReplaceRule { rule, reply } => {
                self.rules.add(rule);
                self.publish();
                Outgoing::Request {
                    message: replace_rule_request(&rule),
                    awaiter: Awaiter::Caller(reply),
                }
            }
            Command::Pull(waiter) => Outgoing::Pull(waiter),
            Command::Shutdown => Outgoing::Shutdown,
        }
    }

    /// The requests that set a new connection's queue up like the last one: the data mode,
    /// then the rules in their order.
    pub fn delivery_requests(&self) -> Vec<Message> {
        std::iter::once(data_mode_request(self.data_mode))
            .chain(self.rules.as_slice().iter().map(replace_rule_request))
            .collect()
    }

    /// The subscriptions to restore.
    pub fn subscriptions(&self) -> Vec<(Interface, u16)> {
        self.subscriptions.iter().copied().collect()
    }
}

fn data_mode_request(mode: DataMode) -> Message {
    to_server(
        player::REQ_DATAMODE,
        Body::Player(Player::DataMode(mode.to_request())),
    )
}

fn replace_rule_request(rule: &ReplaceRule) -> Message {
    to_server(
        player::REQ_ADD_REPLACE_RULE,
        Body::Player(Player::AddReplaceRule(rule.to_request())),
    )
}

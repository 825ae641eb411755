//! What the handle asks of the robot thread: requests, commands, subscriptions, the data mode,
//! replace rules, PULL rounds. Each is a command to the thread, which alone changes the
//! session; the blocking forms wait for its answer, with a timeout.

use std::sync::mpsc;
use std::time::Duration;

use super::commands::Command;
use super::handle::Client;
use super::requests::{PendingReply, ReplySender, RequestError, thread_ended};
use super::{DataMode, ReplaceRule};
use crate::access::observer_may_send;
use crate::interfaces::player::{self, Player};
use crate::message::{Body, Message};
use crate::wire::{DevAddr, MsgType};

/// How much longer than the request timeout a caller waits: the thread enforces the timeout,
/// so this only guards against a stuck thread.
const STUCK_THREAD_MARGIN: Duration = Duration::from_secs(1);

impl Client {
    /// Sends a command to the thread; the reply arrives later.
    fn ask(&self, command: impl FnOnce(ReplySender) -> Command) -> PendingReply {
        let (reply, receiver) = mpsc::channel();
        if self.commands.send(command(reply.clone())).is_err() {
            let _ = reply.send(Err(thread_ended()));
        }
        PendingReply(receiver)
    }

    fn wait(&self, pending: PendingReply) -> Result<Message, RequestError> {
        pending.wait(self.options.request_timeout + STUCK_THREAD_MARGIN)
    }

    /// Refuses what a read-only client must not send.
    fn check_read_only(&self, message: &Message) -> Result<(), RequestError> {
        if self.options.read_only && !observer_may_send(message) {
            return Err(RequestError::ReadOnly(message.header.to_string()));
        }
        Ok(())
    }

    /// Sends a request; the reply arrives later. A read-only client's configuration request
    /// fails at once with [`RequestError::ReadOnly`].
    pub fn request_async(&self, addr: DevAddr, subtype: u8, body: Body) -> PendingReply {
        let message = Message::new(
            self.addr(addr.interf, addr.index),
            MsgType::Req,
            subtype,
            body,
        );
        if let Err(refused) = self.check_read_only(&message) {
            let (reply, receiver) = mpsc::channel();
            let _ = reply.send(Err(refused));
            return PendingReply(receiver);
        }
        self.ask(|reply| Command::Request { message, reply })
    }

    /// Sends a request and waits for its ACK (a NACK or the timeout is an error).
    pub fn request(&self, addr: DevAddr, subtype: u8, body: Body) -> Result<Message, RequestError> {
        self.wait(self.request_async(addr, subtype, body))
    }

    /// Sends a command (fire and forget). The subtype follows from the typed body. A
    /// read-only client sends nothing and logs why; [`Client::try_command`] returns it.
    pub fn command(&self, addr: DevAddr, body: impl Into<Body>) {
        if let Err(e) = self.try_command(addr, body) {
            tracing::warn!(port = self.port, "command dropped: {e}");
        }
    }

    /// Sends a command, saying whether it went to the robot thread: a read-only client
    /// refuses it with [`RequestError::ReadOnly`].
    pub fn try_command(&self, addr: DevAddr, body: impl Into<Body>) -> Result<(), RequestError> {
        let body = body.into();
        let Some((_, subtype)) = body.kind() else {
            return Err(RequestError::Untyped(format!("{addr}")));
        };
        let message = Message::new(
            self.addr(addr.interf, addr.index),
            MsgType::Cmd,
            subtype,
            body,
        );
        self.check_read_only(&message)?;
        self.commands
            .send(Command::Send(message))
            .map_err(|_| thread_ended())
    }

    /// Whether this client refuses commands and configuration requests.
    pub fn is_read_only(&self) -> bool {
        self.options.read_only
    }

    /// Subscribes to a device; returns its driver name. An ACK that carries an error access is
    /// an error. The subscription holds until the server refuses it or it is unsubscribed:
    /// if the server is away now, it is made on the next connection, and it is restored after
    /// every reconnect.
    pub fn subscribe(&self, addr: DevAddr) -> Result<String, RequestError> {
        let reply = self.wait(self.subscribe_async(addr))?;
        match reply.body {
            Body::Player(Player::Device(d)) if d.access == player::OPEN_MODE => {
                Ok(d.driver_name.as_str().into_owned())
            }
            Body::Player(Player::Device(d)) => Err(RequestError::AccessDenied(d.access)),
            _ => Err(RequestError::AccessDenied(player::ERROR_MODE)),
        }
    }

    /// Subscribes without waiting: data is kept from now on and the reply arrives later (check
    /// its access). For a UI that must not block on a slow server.
    pub fn subscribe_async(&self, addr: DevAddr) -> PendingReply {
        let device = (addr.interf, addr.index);
        self.ask(|reply| Command::Subscribe { device, reply })
    }

    /// Unsubscribes and forgets the device's data.
    pub fn unsubscribe(&self, addr: DevAddr) -> Result<(), RequestError> {
        self.wait(self.unsubscribe_async(addr)).map(|_| ())
    }

    /// Unsubscribes without waiting: the client's thread forgets the device's data when it
    /// takes the command, and the reply arrives later. For a UI thread letting a device go,
    /// which must not block on a slow server.
    pub fn unsubscribe_async(&self, addr: DevAddr) -> PendingReply {
        let device = (addr.interf, addr.index);
        self.ask(|reply| Command::Unsubscribe { device, reply })
    }

    /// Switches between PUSH and PULL at run time. The mode holds from now on, so it is
    /// restored after a reconnect even if this request fails because the server is away at
    /// the moment.
    pub fn set_data_mode(&self, mode: DataMode) -> Result<(), RequestError> {
        self.wait(self.ask(|reply| Command::SetDataMode { mode, reply }))
            .map(|_| ())
    }

    /// Adds a replace rule to this connection's queue on the server. It holds like the data
    /// mode and is replayed in order after a reconnect.
    ///
    /// The server tries rules in the order they were added and the first match decides, so a
    /// narrow rule added after a broader one that matches the same messages (such as the
    /// default of [`super::ClientOptions::replace_old_data`]) has no effect; re-adding a rule
    /// with the same filters changes its action instead.
    pub fn add_replace_rule(&self, rule: ReplaceRule) -> Result<(), RequestError> {
        self.wait(self.ask(|reply| Command::AddReplaceRule { rule, reply }))
            .map(|_| ())
    }

    /// PULL mode: asks for a round of data and waits for its SYNCH; returns how many DATA
    /// messages the round brought (stored as usual). A round with no data has no SYNCH, so
    /// this times out if no subscribed device publishes.
    pub fn pull(&self) -> Result<usize, RequestError> {
        let (waiter, receiver) = mpsc::channel();
        let _ = self.commands.send(Command::Pull(waiter));
        let timeout = self.options.request_timeout;
        match receiver.recv_timeout(timeout) {
            Ok(outcome) => outcome,
            Err(mpsc::RecvTimeoutError::Timeout) => Err(RequestError::Timeout(timeout)),
            Err(mpsc::RecvTimeoutError::Disconnected) => Err(thread_ended()),
        }
    }
}

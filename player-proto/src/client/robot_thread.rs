//! The thread that owns one robot's connection and session: it connects, serves the session
//! (see `serve`), and when the server goes away, reconnects with backoff — taking the
//! handle's commands in meanwhile, so that what they change is restored on the next
//! connection.

use std::sync::Arc;
use std::time::Duration;

use tokio::sync::mpsc::UnboundedReceiver;
use tokio::time::Instant;

use super::commands::Command;
use super::options::ClientOptions;
use super::published::{Board, ConnectionState};
use super::requests::RequestError;
use super::session_state::{Outgoing, SessionState};
use super::store::DataStore;
use super::tap::{ConnectionTap, TapEvent};
use crate::message::Message;

/// Why a connection ended.
pub(super) enum End {
    Shutdown,
    Lost(String),
    /// Not worth retrying (not a Player server, Player 1.x).
    Fatal(String),
}

impl End {
    pub fn why(&self) -> String {
        match self {
            End::Shutdown => "client closed".to_string(),
            End::Lost(w) | End::Fatal(w) => w.clone(),
        }
    }
}

/// The thread body, for a client with a thread of its own.
pub(crate) fn run(mut robot: Robot) {
    let runtime = match tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
    {
        Ok(r) => r,
        Err(e) => {
            let failed = ConnectionState::Failed(format!("no runtime: {e}"));
            robot.board.publish(|s| s.state = failed);
            return;
        }
    };
    runtime.block_on(robot.run());
}

pub(super) struct Robot {
    pub host: String,
    pub port: u16,
    pub options: ClientOptions,
    pub board: Arc<Board>,
    pub store: Arc<DataStore>,
    pub session: SessionState,
    pub commands: UnboundedReceiver<Command>,
    /// A connection was lost and none has completed its handshake since.
    pub reconnecting: bool,
    /// This connection's tap, from `options.tap`.
    pub tap: Option<ConnectionTap>,
}

impl Robot {
    /// A connection that has not started; [`Robot::run`] runs it until shutdown.
    pub fn new(
        host: String,
        port: u16,
        options: ClientOptions,
        session: SessionState,
        board: Arc<Board>,
        store: Arc<DataStore>,
        commands: UnboundedReceiver<Command>,
    ) -> Robot {
        let tap = options.tap.as_ref().map(|tap| tap(&host, port));
        Robot {
            tap,
            host,
            port,
            options,
            board,
            store,
            session,
            commands,
            reconnecting: false,
        }
    }

    pub async fn run(&mut self) {
        // Failed attempts since a session last worked. A connection that is accepted but never
        // works (a banner, then garbage) does not count as working, or such a server would be
        // retried at the shortest delay forever.
        let mut attempt = 0u32;
        loop {
            self.set_state(if attempt == 0 {
                ConnectionState::Connecting
            } else {
                ConnectionState::Reconnecting { attempt }
            });
            let (end, worked) = match self.open().await {
                Ok(link) => self.serve(link).await,
                Err(end) => (end, false),
            };
            if worked {
                attempt = 0;
            }
            if let End::Lost(why) | End::Fatal(why) = &end {
                let why = why.clone();
                self.board.publish(|s| s.last_disconnect = Some(why));
            }
            match end {
                End::Shutdown => return,
                End::Fatal(why) => {
                    tracing::error!(host = %self.host, port = self.port, "{why}");
                    self.give_up(why).await;
                    return;
                }
                End::Lost(why) => {
                    tracing::warn!(host = %self.host, port = self.port, "connection lost: {why}");
                    self.reconnecting = true;
                    attempt += 1;
                    let backoff = self.options.backoff;
                    if backoff.max_attempts.is_some_and(|max| attempt > max) {
                        let why = format!("gave up after {} attempts: {why}", attempt - 1);
                        self.give_up(why).await;
                        return;
                    }
                    self.set_state(ConnectionState::Reconnecting { attempt });
                    if self.wait_refusing(backoff.delay(attempt), &why).await {
                        return;
                    }
                }
            }
        }
    }

    /// Tells the tap that an established connection ended.
    pub fn tap_closed(&self, end: &End) {
        if let Some(tap) = &self.tap {
            tap(std::time::SystemTime::now(), TapEvent::Closed(&end.why()));
        }
    }

    /// Publishes the connection state and tells the notifier, so that whoever redraws or
    /// relays on new data also learns that the server went or came back.
    pub fn set_state(&self, state: ConnectionState) {
        self.board.publish(|s| s.state = state);
        if let Some(notify) = &self.options.notifier {
            notify();
        }
    }

    /// Counts and logs a message from the server that could not be used.
    pub fn reject(&self, what: &str) {
        self.board.publish(|s| s.rejected += 1);
        tracing::warn!(host = %self.host, port = self.port, "ignored {what}");
    }

    /// Stores a DATA message of a subscribed device and tells the notifier.
    pub fn keep_data(&self, message: Message) {
        let a = message.header.addr;
        if !self.session.is_subscribed(a.interf, a.index) {
            return;
        }
        let size = message.header.size as usize;
        self.store.store(message, size);
        if let Some(notify) = &self.options.notifier {
            notify();
        }
    }

    /// Takes commands in for `delay`, answering what needs the server with `Disconnected`.
    /// Returns true on shutdown.
    async fn wait_refusing(&mut self, delay: Duration, why: &str) -> bool {
        let until = Instant::now() + delay;
        loop {
            tokio::select! {
                _ = tokio::time::sleep_until(until) => return false,
                command = self.commands.recv() => {
                    if self.refuse(command, why) {
                        return true;
                    }
                }
            }
        }
    }

    async fn give_up(&mut self, why: String) {
        self.set_state(ConnectionState::Failed(why.clone()));
        loop {
            let command = self.commands.recv().await;
            if self.refuse(command, &why) {
                return;
            }
        }
    }

    /// Takes a command in while there is no connection. Returns true on shutdown (or when the
    /// handle is gone).
    fn refuse(&mut self, command: Option<Command>, why: &str) -> bool {
        let Some(command) = command else { return true };
        let error = || RequestError::Disconnected(why.to_string());
        match self.session.apply(command, &self.store) {
            Outgoing::Shutdown => return true,
            Outgoing::Request { awaiter, .. } => awaiter.fail(error()),
            Outgoing::Pull(waiter) => {
                let _ = waiter.send(Err(error()));
            }
            Outgoing::Send(_) => {}
        }
        false
    }
}

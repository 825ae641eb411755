//! Serving one connection after its handshake: reading, decoding and storing what the server
//! sends, and carrying out the handle's commands, until the connection ends.

use std::time::Duration;

use tokio::time::Instant;

use super::commands::PullWaiter;
use super::link::Link;
use super::liveness::{Liveness, Verdict};
use super::published::ConnectionState;
use super::requests::{Awaiter, PendingRequests, RequestError, Resolved};
use super::robot_thread::{End, Robot};
use super::session_state::{Outgoing, to_server};
use crate::interfaces::player;
use crate::message::{Body, Message};
use crate::transport::Incoming;
use crate::wire::MsgType;

/// How long to sleep when nothing has a deadline (the loop wakes on input anyway).
const IDLE_WAKE: Duration = Duration::from_secs(3600);

/// The state of one connection's serving.
struct Serving {
    pending: PendingRequests,
    /// Callers waiting for the end of a PULL round.
    pulls: Vec<PullWaiter>,
    data_in_round: usize,
    liveness: Liveness,
    /// A message was decoded after the handshake: the session works, whatever happens next.
    worked: bool,
}

impl Robot {
    /// Shakes hands, then serves until the connection ends. Returns why it ended and whether
    /// the session worked before that.
    pub(super) async fn serve(&mut self, mut link: Link) -> (End, bool) {
        if let Err(end) = self.handshake(&mut link).await {
            self.tap_closed(&end);
            return (end, false);
        }
        // Logged before the state changes, so that whoever sees `Connected` finds it logged.
        if std::mem::take(&mut self.reconnecting) {
            tracing::info!(host = %self.host, port = self.port, "reconnected");
        }
        self.set_state(ConnectionState::Connected);
        let mut serving = Serving {
            pending: PendingRequests::default(),
            pulls: Vec::new(),
            data_in_round: 0,
            liveness: Liveness::new(self.options.stall_timeout),
            worked: false,
        };
        let end = loop {
            if let Err(end) = self.serve_once(&mut link, &mut serving).await {
                break end;
            }
        };
        self.tap_closed(&end);
        let why = end.why();
        serving.pending.fail_all(&why);
        for waiter in serving.pulls {
            let _ = waiter.send(Err(RequestError::Disconnected(why.clone())));
        }
        (end, serving.worked)
    }

    /// Waits for the next input, command or deadline and handles it.
    async fn serve_once(&mut self, link: &mut Link, serving: &mut Serving) -> Result<(), End> {
        let deadline = [serving.pending.next_deadline(), serving.liveness.deadline()]
            .into_iter()
            .flatten()
            .min()
            .unwrap_or_else(|| Instant::now() + IDLE_WAKE);
        tokio::select! {
            incoming = link.read() => {
                match serving.liveness.heard(incoming) {
                    Ok(Incoming::Message(message)) => {
                        serving.worked = true;
                        self.received(message, serving);
                    }
                    Ok(Incoming::Undecodable(e)) => self.reject(&e.to_string()),
                    Ok(Incoming::Closed) => {
                        return Err(End::Lost("the server closed the connection".into()));
                    }
                    Err(e) => return Err(End::Lost(e.to_string())),
                }
            }
            command = self.commands.recv() => {
                let Some(command) = command else { return Err(End::Shutdown) };
                match self.session.apply(command, &self.store) {
                    Outgoing::Shutdown => return Err(End::Shutdown),
                    Outgoing::Send(message) => link.send(&message).await?,
                    Outgoing::Request { message, awaiter } => {
                        if serving.pending.len() >= self.options.max_pending_requests {
                            awaiter.fail(RequestError::TooManyPending(serving.pending.len()));
                            return Ok(());
                        }
                        serving.pending.add(&message, self.options.request_timeout, awaiter);
                        link.send(&message).await?;
                    }
                    Outgoing::Pull(waiter) => {
                        serving.data_in_round = 0;
                        serving.pulls.push(waiter);
                        // Its ACK comes first in the round; expected, so not a reply to nothing.
                        let request = to_server(player::REQ_DATA, Body::Empty);
                        serving.pending.add(&request, self.options.request_timeout, Awaiter::Nobody);
                        link.send(&request).await?;
                    }
                }
            }
            _ = tokio::time::sleep_until(deadline) => {
                let now = Instant::now();
                serving.pending.expire(now);
                match serving.liveness.check(now) {
                    Verdict::Alive => {}
                    Verdict::Stalled(why) => return Err(End::Lost(why)),
                    Verdict::Probe => {
                        let probe = to_server(player::REQ_DEVLIST, Body::Empty);
                        serving.pending.add(&probe, serving.liveness.timeout(), Awaiter::Nobody);
                        link.send(&probe).await?;
                    }
                }
            }
        }
        Ok(())
    }

    fn received(&mut self, message: Message, serving: &mut Serving) {
        match message.header.msg_type {
            MsgType::Data => {
                serving.data_in_round += 1;
                self.keep_data(message);
            }
            MsgType::Ack | MsgType::Nack => match serving.pending.resolve(message) {
                Resolved::Delivered => {}
                Resolved::Subscription { device, granted } => {
                    self.session
                        .settle_subscription(device, granted, &self.store);
                }
                Resolved::Orphan(orphan) => {
                    self.reject(&format!("a reply to nothing: {}", orphan.header));
                }
            },
            MsgType::Synch => {
                for waiter in serving.pulls.drain(..) {
                    let _ = waiter.send(Ok(serving.data_in_round));
                }
                serving.data_in_round = 0;
            }
            other => self.reject(&format!("a {other} message from a server")),
        }
    }
}

//! The thread that owns one robot's connection: it connects, shakes hands (data mode, replace
//! rule, device list, driver names, subscriptions), then reads, decodes and stores data while
//! sending what the handle asks — and when the server goes away, reconnects with backoff and
//! restores everything.

use std::sync::Arc;
use std::time::Duration;

use bytes::BytesMut;
use tokio::net::TcpStream;
use tokio::net::tcp::{OwnedReadHalf, OwnedWriteHalf};
use tokio::sync::mpsc::UnboundedReceiver;
use tokio::time::Instant;

use super::liveness::{Liveness, Verdict};
use super::options::{ClientOptions, DataMode};
use super::requests::{PendingRequests, ReplySender, RequestError};
use super::shared::{ConnectionState, DeviceInfo, Shared};
use crate::interfaces::player::{self, DataModeReq, DeviceReq, DriverInfo, Player};
use crate::message::{Body, Message};
use crate::transport::{Incoming, MessageReader, TransportError, write_message};
use crate::wire::{DevAddr, FrameDecoder, Interface, MsgType, PlayerString};

/// What the handle asks of the thread.
pub(crate) enum Command {
    Request {
        message: Message,
        timeout: Duration,
        reply: ReplySender,
    },
    /// Fire and forget.
    Send(Message),
    /// PULL: ask for a round of data; answered with the number of DATA messages at SYNCH.
    Pull(std::sync::mpsc::Sender<Result<usize, RequestError>>),
    Shutdown,
}

/// Why a connection ended.
enum End {
    Shutdown,
    Lost(String),
    /// Not worth retrying (not a Player server, Player 1.x).
    Fatal(String),
}

struct Link {
    reader: MessageReader<OwnedReadHalf>,
    writer: OwnedWriteHalf,
    scratch: BytesMut,
}

/// The thread body.
pub(crate) fn run(
    host: String,
    port: u16,
    options: ClientOptions,
    shared: Arc<Shared>,
    commands: UnboundedReceiver<Command>,
) {
    let runtime = match tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
    {
        Ok(r) => r,
        Err(e) => {
            shared.set_state(ConnectionState::Failed(format!("no runtime: {e}")));
            return;
        }
    };
    let mut robot = Robot {
        host,
        port,
        options,
        shared,
        commands,
    };
    runtime.block_on(robot.run());
}

struct Robot {
    host: String,
    port: u16,
    options: ClientOptions,
    shared: Arc<Shared>,
    commands: UnboundedReceiver<Command>,
}

impl Robot {
    async fn run(&mut self) {
        let mut attempt = 0u32;
        loop {
            self.shared.set_state(if attempt == 0 {
                ConnectionState::Connecting
            } else {
                ConnectionState::Reconnecting { attempt }
            });
            let end = match self.connect().await {
                Ok(link) => {
                    attempt = 0;
                    self.session(link).await
                }
                Err(end) => end,
            };
            if let End::Lost(why) | End::Fatal(why) = &end {
                *self.shared.last_disconnect.lock().expect("last disconnect") = Some(why.clone());
            }
            match end {
                End::Shutdown => return,
                End::Fatal(why) => {
                    tracing::error!(host = %self.host, port = self.port, "{why}");
                    self.shared.set_state(ConnectionState::Failed(why.clone()));
                    self.refuse_until_shutdown(&why).await;
                    return;
                }
                End::Lost(why) => {
                    tracing::warn!(host = %self.host, port = self.port, "connection lost: {why}");
                    attempt += 1;
                    if self
                        .options
                        .backoff
                        .max_attempts
                        .is_some_and(|max| attempt > max)
                    {
                        let why = format!("gave up after {} attempts: {why}", attempt - 1);
                        self.shared.set_state(ConnectionState::Failed(why.clone()));
                        self.refuse_until_shutdown(&why).await;
                        return;
                    }
                    self.shared
                        .set_state(ConnectionState::Reconnecting { attempt });
                    if self
                        .wait_refusing(self.options.backoff.delay(attempt), &why)
                        .await
                    {
                        return;
                    }
                }
            }
        }
    }

    /// Answers commands with `Disconnected` for `delay`. Returns true on shutdown.
    async fn wait_refusing(&mut self, delay: Duration, why: &str) -> bool {
        let until = Instant::now() + delay;
        loop {
            tokio::select! {
                _ = tokio::time::sleep_until(until) => return false,
                command = self.commands.recv() => match command {
                    None | Some(Command::Shutdown) => return true,
                    Some(other) => refuse(other, why),
                },
            }
        }
    }

    async fn refuse_until_shutdown(&mut self, why: &str) {
        while let Some(command) = self.commands.recv().await {
            if matches!(command, Command::Shutdown) {
                return;
            }
            refuse(command, why);
        }
    }

    async fn connect(&mut self) -> Result<Link, End> {
        let timeout = self.options.connect_timeout;
        let stream =
            tokio::time::timeout(timeout, TcpStream::connect((self.host.as_str(), self.port)))
                .await
                .map_err(|_| End::Lost(format!("no connection within {timeout:?}")))?
                .map_err(|e| End::Lost(e.to_string()))?;
        let _ = stream.set_nodelay(true);
        let (read, writer) = stream.into_split();
        let mut reader = MessageReader::new(read, FrameDecoder::new(self.options.max_body));
        let banner = tokio::time::timeout(timeout, reader.read_banner())
            .await
            .map_err(|_| End::Lost(format!("no banner within {timeout:?}")))?
            .map_err(|e| match e {
                TransportError::Frame(f) => End::Fatal(f.to_string()),
                other => End::Lost(other.to_string()),
            })?;
        if !banner.has_3x_layouts() {
            tracing::warn!(%banner, "Player 2.0 lays out many bodies differently from 3.x; data may be misread");
        }
        *self.shared.banner.lock().expect("banner") = Some(banner);
        Ok(Link {
            reader,
            writer,
            scratch: BytesMut::with_capacity(4096),
        })
    }

    /// Handshake, then serve until the connection ends.
    async fn session(&mut self, mut link: Link) -> End {
        if let Err(end) = self.handshake(&mut link).await {
            return end;
        }
        self.shared.set_state(ConnectionState::Connected);
        let mut pending = PendingRequests::default();
        let mut pulls: Vec<std::sync::mpsc::Sender<Result<usize, RequestError>>> = Vec::new();
        let mut data_in_round = 0usize;
        let mut liveness = Liveness::new(self.options.stall_timeout);
        let end = loop {
            let deadline = [pending.next_deadline(), liveness.deadline()]
                .into_iter()
                .flatten()
                .min()
                .unwrap_or_else(|| Instant::now() + Duration::from_secs(3600));
            tokio::select! {
                incoming = link.reader.read() => match liveness.heard(incoming) {
                    Ok(Incoming::Message(message)) => match message.header.msg_type {
                        MsgType::Data => {
                            data_in_round += 1;
                            self.store(message);
                        }
                        MsgType::Ack | MsgType::Nack => {
                            if let Some(orphan) = pending.resolve(message) {
                                self.reject(&format!("a reply to nothing: {}", orphan.header));
                            }
                        }
                        MsgType::Synch => {
                            for waiter in pulls.drain(..) {
                                let _ = waiter.send(Ok(data_in_round));
                            }
                            data_in_round = 0;
                        }
                        _ => self.reject(&format!("a {} message from a server", message.header.msg_type)),
                    },
                    Ok(Incoming::Undecodable(e)) => self.reject(&e.to_string()),
                    Ok(Incoming::Closed) => break End::Lost("the server closed the connection".into()),
                    Err(e) => break End::Lost(e.to_string()),
                },
                command = self.commands.recv() => match command {
                    None | Some(Command::Shutdown) => break End::Shutdown,
                    Some(Command::Send(message)) => {
                        if let Err(e) = write_message(&mut link.writer, &message, &mut link.scratch).await {
                            break End::Lost(e.to_string());
                        }
                    }
                    Some(Command::Request { message, timeout, reply }) => {
                        if pending.len() >= self.options.max_pending_requests {
                            let _ = reply.send(Err(RequestError::TooManyPending(pending.len())));
                            continue;
                        }
                        let h = message.header;
                        pending.add((h.addr.interf, h.addr.index, h.subtype), timeout, reply);
                        if let Err(e) = write_message(&mut link.writer, &message, &mut link.scratch).await {
                            break End::Lost(e.to_string());
                        }
                    }
                    Some(Command::Pull(waiter)) => {
                        data_in_round = 0;
                        pulls.push(waiter);
                        let request = Message::new(DevAddr::local(Interface::PLAYER, 0), MsgType::Req, player::REQ_DATA, Body::Empty);
                        if let Err(e) = write_message(&mut link.writer, &request, &mut link.scratch).await {
                            break End::Lost(e.to_string());
                        }
                    }
                },
                _ = tokio::time::sleep_until(deadline) => {
                    let now = Instant::now();
                    pending.expire(now);
                    match liveness.check(now) {
                        Verdict::Alive => {}
                        Verdict::Stalled(why) => break End::Lost(why),
                        Verdict::Probe => {
                            // The reply is consumed by the pending table and goes nowhere.
                            let (reply, _) = std::sync::mpsc::channel();
                            let probe = Message::new(DevAddr::local(Interface::PLAYER, 0), MsgType::Req, player::REQ_DEVLIST, Body::Empty);
                            pending.add((Interface::PLAYER, 0, player::REQ_DEVLIST), liveness.timeout(), reply);
                            if let Err(e) = write_message(&mut link.writer, &probe, &mut link.scratch).await {
                                break End::Lost(e.to_string());
                            }
                        }
                    }
                }
            }
        };
        let why = match &end {
            End::Shutdown => "client closed".to_string(),
            End::Lost(w) | End::Fatal(w) => w.clone(),
        };
        pending.fail_all(&why);
        for waiter in pulls {
            let _ = waiter.send(Err(RequestError::Disconnected(why.clone())));
        }
        end
    }

    fn store(&self, message: Message) {
        let size = message.header.size as usize;
        if self.shared.store(message, size)
            && let Some(notify) = &self.options.notifier
        {
            notify();
        }
    }

    fn reject(&self, what: &str) {
        *self.shared.rejected.lock().expect("rejected") += 1;
        tracing::warn!(host = %self.host, port = self.port, "ignored {what}");
    }

    /// Sends a request and waits for its reply, storing any data that arrives meanwhile.
    async fn call(&mut self, link: &mut Link, request: Message) -> Result<Message, End> {
        write_message(&mut link.writer, &request, &mut link.scratch)
            .await
            .map_err(|e| End::Lost(e.to_string()))?;
        let key = (
            request.header.addr.interf,
            request.header.addr.index,
            request.header.subtype,
        );
        let timeout = self.options.request_timeout;
        let deadline = Instant::now() + timeout;
        loop {
            let incoming = tokio::time::timeout_at(deadline, link.reader.read())
                .await
                .map_err(|_| {
                    End::Lost(format!("no reply to {} within {timeout:?}", request.header))
                })?
                .map_err(|e| End::Lost(e.to_string()))?;
            match incoming {
                Incoming::Message(m) if m.header.msg_type.is_reply() => {
                    if (m.header.addr.interf, m.header.addr.index, m.header.subtype) == key {
                        return Ok(m);
                    }
                    self.reject(&format!("a reply to nothing: {}", m.header));
                }
                Incoming::Message(m) if m.header.msg_type == MsgType::Data => self.store(m),
                Incoming::Message(_) => {}
                Incoming::Undecodable(e) => self.reject(&e.to_string()),
                Incoming::Closed => {
                    return Err(End::Lost("the server closed the connection".into()));
                }
            }
        }
    }

    async fn handshake(&mut self, link: &mut Link) -> Result<(), End> {
        let server = DevAddr::local(Interface::PLAYER, 0);
        let req = |subtype, body| Message::new(server, MsgType::Req, subtype, body);
        // What the handle asked for last: the connect-time options, or what was set since.
        let mode = match *self.shared.data_mode.lock().expect("data mode") {
            DataMode::Push => player::DATAMODE_PUSH,
            DataMode::Pull => player::DATAMODE_PULL,
        };
        self.call(
            link,
            req(
                player::REQ_DATAMODE,
                Body::Player(Player::DataMode(DataModeReq { mode })),
            ),
        )
        .await?;
        let rules = self.shared.replace_rules.lock().expect("rules").clone();
        for rule in rules {
            self.call(
                link,
                req(
                    player::REQ_ADD_REPLACE_RULE,
                    Body::Player(Player::AddReplaceRule(rule.to_request())),
                ),
            )
            .await?;
        }
        let list = self
            .call(link, req(player::REQ_DEVLIST, Body::Empty))
            .await?;
        let Body::Player(Player::DevList(list)) = list.body else {
            return Err(End::Lost("the device list reply has no list".into()));
        };
        let mut devices = Vec::with_capacity(list.devices.len());
        for addr in list.devices {
            let ask = DriverInfo {
                addr,
                driver_name: PlayerString::default(),
            };
            let reply = self
                .call(
                    link,
                    req(
                        player::REQ_DRIVERINFO,
                        Body::Player(Player::DriverInfo(ask)),
                    ),
                )
                .await?;
            let driver = match reply.body {
                Body::Player(Player::DriverInfo(info)) => info.driver_name.as_str().into_owned(),
                _ => String::new(),
            };
            devices.push(DeviceInfo { addr, driver });
        }
        *self.shared.devices.lock().expect("devices") = devices;

        let subscriptions: Vec<_> = self
            .shared
            .subscriptions
            .lock()
            .expect("subscriptions")
            .iter()
            .copied()
            .collect();
        for (interf, index) in subscriptions {
            let open = DeviceReq {
                addr: DevAddr::local(interf, index),
                access: player::OPEN_MODE,
                driver_name: PlayerString::default(),
            };
            let reply = self
                .call(
                    link,
                    req(player::REQ_DEV, Body::Player(Player::Device(open))),
                )
                .await?;
            let granted = match &reply.body {
                Body::Player(Player::Device(d)) if reply.header.msg_type == MsgType::Ack => {
                    d.access
                }
                _ => player::ERROR_MODE,
            };
            if granted != player::OPEN_MODE {
                tracing::warn!(
                    port = self.port,
                    "could not resubscribe {interf}:{index} after reconnecting"
                );
            }
        }
        Ok(())
    }
}

fn refuse(command: Command, why: &str) {
    let error = || RequestError::Disconnected(why.to_string());
    match command {
        Command::Request { reply, .. } => {
            let _ = reply.send(Err(error()));
        }
        Command::Pull(waiter) => {
            let _ = waiter.send(Err(error()));
        }
        Command::Send(_) | Command::Shutdown => {}
    }
}

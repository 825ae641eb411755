//! One client connection: the banner, then reading messages and answering them the way a
//! Player 3 server does (§4 and §8.4 of the protocol notes), while a writer task drains the
//! connection's outgoing queue.

use std::net::{IpAddr, Ipv4Addr};
use std::sync::Arc;
use std::sync::atomic::Ordering;
use std::time::{SystemTime, UNIX_EPOCH};

use bytes::BytesMut;
use tokio::io::AsyncWriteExt;
use tokio::net::TcpStream;
use tokio::net::tcp::OwnedWriteHalf;

use super::control::Peer;
use super::device::Reply;
use super::queue::data_request_ack;
use super::state::{DeviceSlot, OpenConnection, ServerState, SessionState};
use crate::delivery::{DataMode, ReplaceRule};
use crate::interfaces::player::{
    self, CLOSE_MODE, DevList, DeviceReq, DriverInfo, ERROR_MODE, OPEN_MODE, Player,
};
use crate::message::{Body, Message};
use crate::transport::{Incoming, MessageReader, write_messages};
use crate::wire::{Banner, DevAddr, FrameDecoder, Interface, MsgType, PlayerString};

fn now() -> f64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map(|d| d.as_secs_f64())
        .unwrap_or(0.0)
}

/// Serves one accepted connection until either side closes it.
pub(crate) async fn serve(
    stream: TcpStream,
    port: u16,
    state: Arc<ServerState>,
    banner: Banner,
    max_body: usize,
    publisher_writes: bool,
) {
    let peer_addr = stream.peer_addr().ok();
    let peer = peer_addr.map_or_else(|| "?".to_string(), |a| a.to_string());
    let _ = stream.set_nodelay(true);
    // A second handle on the socket, for the publisher's own writes (`direct.rs`).
    let direct = publisher_writes
        .then(|| {
            socket2::SockRef::from(&stream)
                .try_clone()
                .map(std::net::TcpStream::from)
                .and_then(|s| s.set_nonblocking(true).map(|()| s))
                .inspect_err(
                    |e| tracing::debug!(%peer, "data will go through the writer task: {e}"),
                )
                .ok()
        })
        .flatten();
    let (read_half, mut write_half) = stream.into_split();
    if let Err(e) = write_half.write_all(&banner.to_bytes()).await {
        tracing::debug!(%peer, "client left before the banner: {e}");
        return;
    }
    let client = Peer {
        id: state.next_peer.fetch_add(1, Ordering::Relaxed),
        ip: peer_addr.map_or(IpAddr::V4(Ipv4Addr::UNSPECIFIED), |a| a.ip()),
    };
    let _open = OpenConnection::new(&state);
    let session = Arc::new(SessionState::new(port, client, &state.queue_rules, direct));
    state.register(&session);
    if let Some(lockstep) = &state.lockstep {
        lockstep.arrived();
    }
    let writer = tokio::spawn(write_loop(write_half, session.clone()));

    let mut reader = MessageReader::new(read_half, FrameDecoder::new(max_body));
    let mut handler = Handler {
        state: &state,
        session: &session,
        port,
    };
    loop {
        match reader.read().await {
            Ok(Incoming::Message(message)) => {
                if message.header.msg_type == MsgType::Cmd
                    && let Some(lockstep) = &state.lockstep
                {
                    lockstep.turn(client.id).await;
                }
                handler.handle(message);
            }
            // Player drops a message whose body does not decode, without a reply.
            Ok(Incoming::Undecodable(e)) => tracing::warn!(%peer, "dropped: {e}"),
            Ok(Incoming::Closed) => break,
            Err(e) => {
                tracing::warn!(%peer, port, "closing the connection: {e}");
                break;
            }
        }
        if session.is_closed() {
            break;
        }
    }
    handler.unsubscribe_all();
    state.gate.left(client);
    if let Some(lockstep) = &state.lockstep {
        lockstep.left(client.id);
    }
    session.close();
    let _ = writer.await;
}

/// Writes what the publisher did not (see `direct.rs`): replies, what a publisher's write
/// left over, and everything when the publisher has no handle on the socket.
async fn write_loop(mut out: OwnedWriteHalf, session: Arc<SessionState>) {
    let mut scratch = BytesMut::with_capacity(64 * 1024);
    loop {
        let turn = session.writer_takes();
        let written = async {
            out.write_all(&turn.leftover).await?;
            write_messages(&mut out, &turn.messages, &mut scratch).await
        }
        .await;
        session.writer_done();
        if let Err(e) = written {
            tracing::debug!("client write failed: {e}");
            session.close();
            return;
        }
        if session.is_closed() {
            let _ = out.shutdown().await;
            return;
        }
        session.wake_writer.notified().await;
    }
}

struct Handler<'a> {
    state: &'a ServerState,
    session: &'a Arc<SessionState>,
    port: u16,
}

impl Handler<'_> {
    fn server_addr(&self, interf: Interface, index: u16) -> DevAddr {
        DevAddr {
            host: self.state.host,
            robot: u32::from(self.port),
            interf,
            index,
        }
    }

    fn reply(&self, request: &Message, kind: MsgType, body: Body) {
        let addr = self.server_addr(request.header.addr.interf, request.header.addr.index);
        let mut reply = Message::new(addr, kind, request.header.subtype, body);
        reply.header.timestamp = now();
        reply.header.seq = request.header.seq;
        self.session.send(Arc::new(reply));
    }

    fn handle(&mut self, message: Message) {
        if message.header.addr.interf == Interface::PLAYER {
            self.handle_player(&message);
            return;
        }
        let (interf, index) = (message.header.addr.interf, message.header.addr.index);
        let Some(slot) = self.state.device(self.port, interf, index) else {
            // Player drops messages to devices it does not have, even requests.
            tracing::debug!(
                port = self.port,
                "dropped a message to unknown device {interf}:{index}"
            );
            return;
        };
        if message.header.msg_type == MsgType::Cmd
            && !slot.device.lock().expect("device").accepts_commands()
        {
            tracing::info!(port = self.port, "refused a command: {}", message.header);
            self.reply(&message, MsgType::Nack, Body::Empty);
            return;
        }
        if matches!(message.body, Body::Unknown(_)) {
            tracing::debug!("dropped {}: no structure for that subtype", message.header);
            return;
        }
        if !self.state.gate.admits(self.session.peer, &message) {
            tracing::debug!(
                port = self.port,
                "refused {} from an observer",
                message.header
            );
            if message.header.msg_type == MsgType::Req {
                self.reply(&message, MsgType::Nack, Body::Empty);
            }
            return;
        }
        let mut message = message;
        message.header.addr = slot.addr;
        match message.header.msg_type {
            MsgType::Cmd => {
                slot.device.lock().expect("device").on_command(&message);
                if let Some(lockstep) = &self.state.lockstep {
                    lockstep.commanded(self.session.peer.id);
                }
            }
            MsgType::Req => match slot.device.lock().expect("device").on_request(&message) {
                Reply::Ack(body) => self.reply(&message, MsgType::Ack, body),
                Reply::Nack => self.reply(&message, MsgType::Nack, Body::Empty),
            },
            other => tracing::debug!("dropped a {other} message sent to a device"),
        }
    }

    fn handle_player(&mut self, message: &Message) {
        let h = &message.header;
        if h.msg_type != MsgType::Req {
            self.reply(message, MsgType::Nack, Body::Empty);
            return;
        }
        match (h.subtype, &message.body) {
            (player::REQ_DEVLIST, _) => {
                let devices = self.state.devices_on(self.port).map(|d| d.addr).collect();
                self.reply(
                    message,
                    MsgType::Ack,
                    Body::Player(Player::DevList(DevList { devices })),
                );
            }
            (player::REQ_DRIVERINFO, Body::Player(Player::DriverInfo(asked))) => {
                match self
                    .state
                    .device(self.port, asked.addr.interf, asked.addr.index)
                {
                    Some(slot) => {
                        let name =
                            PlayerString::new(slot.device.lock().expect("device").driver_name());
                        let info = DriverInfo {
                            addr: slot.addr,
                            driver_name: name,
                        };
                        self.reply(
                            message,
                            MsgType::Ack,
                            Body::Player(Player::DriverInfo(info)),
                        );
                    }
                    None => self.reply(message, MsgType::Nack, Body::Empty),
                }
            }
            (player::REQ_DEV, Body::Player(Player::Device(req))) => self.subscription(message, req),
            (player::REQ_DATAMODE, Body::Player(Player::DataMode(m))) => {
                // Player ignores an unknown mode but still ACKs.
                if let Some(mode) = DataMode::from_request(m) {
                    self.session.queue.lock().expect("queue").set_mode(mode);
                }
                self.reply(message, MsgType::Ack, Body::Empty);
            }
            (player::REQ_DATA, Body::Empty) => {
                let ack = data_request_ack(self.state.host, u32::from(self.port));
                self.session
                    .queue
                    .lock()
                    .expect("queue")
                    .request_data(Arc::new(ack));
                self.session.wake_writer.notify_one();
            }
            (player::REQ_ADD_REPLACE_RULE, Body::Player(Player::AddReplaceRule(r))) => {
                // A rule no message can match changes nothing; Player ACKs it all the same.
                if let Some(rule) = ReplaceRule::from_request(r) {
                    self.session.queue.lock().expect("queue").add_rule(rule);
                }
                self.reply(message, MsgType::Ack, Body::Empty);
            }
            // A body where none belongs, or a request Player's TCP layer does not implement
            // (AUTH, NAMESERVICE): Player drops the former and NACKs the latter.
            (player::REQ_DATA, _) => tracing::debug!("dropped a data request with a body"),
            _ => self.reply(message, MsgType::Nack, Body::Empty),
        }
    }

    fn subscription(&mut self, message: &Message, req: &DeviceReq) {
        let (interf, index) = (req.addr.interf, req.addr.index);
        let Some(slot) = self.state.device(self.port, interf, index) else {
            let refused = DeviceReq {
                addr: self.server_addr(interf, index),
                access: ERROR_MODE,
                driver_name: PlayerString::default(),
            };
            self.reply(
                message,
                MsgType::Nack,
                Body::Player(Player::Device(refused)),
            );
            return;
        };
        let mut device = slot.device.lock().expect("device");
        let key = (interf, index);
        let mut greeting = Vec::new();
        let granted = match req.access {
            OPEN_MODE => {
                // The device's hook runs with no session lock held: a device may take its own
                // locks (a simulation's), which a publishing thread holds while it asks who is
                // subscribed — holding both here, in the other order, deadlocked the two.
                let subscribed = self
                    .session
                    .subscriptions
                    .lock()
                    .expect("subscriptions")
                    .contains(&key);
                if subscribed || device.on_subscribe() {
                    let added = self
                        .session
                        .subscriptions
                        .lock()
                        .expect("subscriptions")
                        .insert(key);
                    if added {
                        slot.subscribers().push(self.session.clone());
                        greeting = device.greeting();
                    }
                    OPEN_MODE
                } else {
                    ERROR_MODE
                }
            }
            CLOSE_MODE => {
                if self
                    .session
                    .subscriptions
                    .lock()
                    .expect("subscriptions")
                    .remove(&key)
                {
                    self.leave(slot);
                    device.on_unsubscribe();
                }
                CLOSE_MODE
            }
            _ => ERROR_MODE,
        };
        let reply = DeviceReq {
            addr: slot.addr,
            access: granted,
            driver_name: PlayerString::new(device.driver_name()),
        };
        drop(device);
        self.reply(message, MsgType::Ack, Body::Player(Player::Device(reply)));
        for (subtype, body, time) in greeting {
            let data = Message::new(slot.addr, MsgType::Data, subtype, body).at(time);
            self.session.send(Arc::new(data));
        }
    }

    fn unsubscribe_all(&mut self) {
        let subs: Vec<_> = self
            .session
            .subscriptions
            .lock()
            .expect("subscriptions")
            .drain()
            .collect();
        for (interf, index) in subs {
            if let Some(slot) = self.state.device(self.port, interf, index) {
                let mut device = slot.device.lock().expect("device");
                self.leave(slot);
                device.on_unsubscribe();
            }
        }
    }

    /// Takes this connection off the device's subscriber list.
    fn leave(&self, slot: &DeviceSlot) {
        slot.subscribers().retain(|s| !Arc::ptr_eq(s, self.session));
    }
}

//! Observers for a [`Crowd`]: each a plain Player client — banner, a subscription per device, then reading —
//! that takes the latency of every DATA message from the send time in its header to the
//! moment it is decoded here.

use std::time::Duration;

use bytes::BytesMut;
use player_proto::interfaces::player::{self, DeviceReq, Player};
use player_proto::message::{Body, Message};
use player_proto::transport::{Incoming, MessageReader, write_message};
use player_proto::wire::{DevAddr, FrameDecoder, MsgType, PlayerString};
use tokio::net::TcpStream;

use crate::BenchError;
use crate::clock::{SharedWindow, unix_seconds};
use crate::crowd::{Crowd, Member, Seen};
use crate::traffic::DEVICES;

/// Connects `count` observers spread evenly over `ports` and waits (at most `timeout`)
/// until every one has its subscriptions granted.
pub fn connect_observers(
    ports: &[u16],
    count: usize,
    window: SharedWindow,
    timeout: Duration,
) -> Result<Crowd, BenchError> {
    if ports.is_empty() {
        return Err(BenchError::Config("observers need ports".into()));
    }
    let ports = ports.to_vec();
    Crowd::start("observers", count, window, timeout, move |member| {
        observe(ports[member.index % ports.len()], member)
    })
}

fn subscription(addr: DevAddr) -> Message {
    let req = DeviceReq {
        addr,
        access: player::OPEN_MODE,
        driver_name: PlayerString::default(),
    };
    Message::new(
        DevAddr::local(player_proto::wire::Interface::PLAYER, 0),
        MsgType::Req,
        player::REQ_DEV,
        Body::Player(Player::Device(req)),
    )
}

async fn observe(port: u16, member: Member) -> Seen {
    let Member {
        window,
        mut stop,
        ready,
        ..
    } = member;
    let stream = TcpStream::connect(("127.0.0.1", port))
        .await
        .map_err(|e| format!("connect to {port}: {e}"))?;
    let _ = stream.set_nodelay(true);
    let (read, mut write) = stream.into_split();
    let mut reader = MessageReader::new(read, FrameDecoder::default());
    reader.read_banner().await.map_err(|e| e.to_string())?;
    let mut scratch = BytesMut::new();
    for interf in DEVICES {
        let open = subscription(DevAddr::local(interf, 0));
        write_message(&mut write, &open, &mut scratch)
            .await
            .map_err(|e| e.to_string())?;
    }
    let mut granted = 0;
    let mut latencies = Vec::new();
    loop {
        tokio::select! {
            _ = stop.changed() => return Ok(latencies),
            incoming = reader.read() => match incoming.map_err(|e| e.to_string())? {
                Incoming::Message(m) if m.header.msg_type == MsgType::Data => {
                    let sent = m.header.timestamp;
                    if window.contains(sent) {
                        latencies.push(unix_seconds() - sent);
                    }
                }
                Incoming::Message(m) if m.header.msg_type == MsgType::Ack => {
                    granted += 1;
                    if granted == DEVICES.len() {
                        let _ = ready.send(()).await;
                    }
                }
                Incoming::Message(_) | Incoming::Undecodable(_) => {}
                Incoming::Closed => return Err(format!("port {port} closed the connection")),
            },
        }
    }
}

//! Opening a connection: TCP, the banner, then the handshake that sets the session up again —
//! data mode, replace rules, device list, driver names, subscriptions.

use std::time::SystemTime;

use bytes::{Bytes, BytesMut};
use tokio::net::TcpStream;
use tokio::net::tcp::{OwnedReadHalf, OwnedWriteHalf};
use tokio::time::Instant;

use super::published::DeviceInfo;
use super::requests::granted;
use super::robot_thread::{End, Robot};
use super::session_state::{device_request, to_server};
use super::tap::{ConnectionTap, TapEvent};
use crate::capture::Direction;
use crate::interfaces::player::{self, DriverInfo, Player};
use crate::message::{Body, Message};
use crate::transport::{Incoming, MessageReader, TransportError, write_message};
use crate::wire::{FrameDecoder, HEADER_LEN, Header, MsgType, PlayerString};

pub(super) struct Link {
    pub reader: MessageReader<OwnedReadHalf>,
    pub writer: OwnedWriteHalf,
    pub scratch: BytesMut,
    pub tap: Option<ConnectionTap>,
}

/// Room for a typical request's encoding, so sending seldom allocates.
const SCRATCH_CAPACITY: usize = 4096;

impl Link {
    pub async fn send(&mut self, message: &Message) -> Result<(), End> {
        write_message(&mut self.writer, message, &mut self.scratch)
            .await
            .map_err(|e| End::Lost(e.to_string()))?;
        if let Some(tap) = &self.tap {
            tap_sent(tap, &self.scratch);
        }
        Ok(())
    }

    /// The next message, shown to the tap first, as received.
    pub async fn read(&mut self) -> Result<Incoming, TransportError> {
        let Some(tap) = &self.tap else {
            return self.reader.read().await;
        };
        let frame = self.reader.read_frame().await?;
        if let Some(frame) = &frame {
            let event = TapEvent::Frame {
                direction: Direction::ServerToClient,
                header: &frame.header,
                body: &frame.body,
            };
            tap(SystemTime::now(), event);
        }
        Ok(Incoming::decode(frame))
    }
}

/// Shows the tap a message just sent, from its encoding.
fn tap_sent(tap: &ConnectionTap, encoded: &[u8]) {
    if let Some(Ok(header)) = Header::decode_slice(encoded) {
        let body = Bytes::copy_from_slice(&encoded[HEADER_LEN..]);
        let event = TapEvent::Frame {
            direction: Direction::ClientToServer,
            header: &header,
            body: &body,
        };
        tap(SystemTime::now(), event);
    }
}

impl Robot {
    /// Connects and reads the banner.
    pub(super) async fn open(&mut self) -> Result<Link, End> {
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
        if let Some(tap) = &self.tap {
            tap(SystemTime::now(), TapEvent::Opened(&banner));
        }
        self.board.publish(|s| s.banner = Some(banner));
        Ok(Link {
            reader,
            writer,
            scratch: BytesMut::with_capacity(SCRATCH_CAPACITY),
            tap: self.tap.clone(),
        })
    }

    /// Sends a request and waits for its reply, storing any data that arrives meanwhile.
    async fn call(&mut self, link: &mut Link, request: Message) -> Result<Message, End> {
        link.send(&request).await?;
        let key = (
            request.header.addr.interf,
            request.header.addr.index,
            request.header.subtype,
        );
        let timeout = self.options.request_timeout;
        let deadline = Instant::now() + timeout;
        loop {
            let incoming = tokio::time::timeout_at(deadline, link.read())
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
                Incoming::Message(m) if m.header.msg_type == MsgType::Data => self.keep_data(m),
                Incoming::Message(_) => {}
                Incoming::Undecodable(e) => self.reject(&e.to_string()),
                Incoming::Closed => {
                    return Err(End::Lost("the server closed the connection".into()));
                }
            }
        }
    }

    /// Sets the new connection up as the session was: the queue's data mode and rules, the
    /// device list with driver names, and the subscriptions.
    pub(super) async fn handshake(&mut self, link: &mut Link) -> Result<(), End> {
        for request in self.session.delivery_requests() {
            self.call(link, request).await?;
        }
        let list = self
            .call(link, to_server(player::REQ_DEVLIST, Body::Empty))
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
            let ask = to_server(
                player::REQ_DRIVERINFO,
                Body::Player(Player::DriverInfo(ask)),
            );
            let driver = match self.call(link, ask).await?.body {
                Body::Player(Player::DriverInfo(info)) => info.driver_name.as_str().into_owned(),
                _ => String::new(),
            };
            devices.push(DeviceInfo { addr, driver });
        }
        self.board.publish(|s| s.devices = devices);

        for (interf, index) in self.session.subscriptions() {
            let open = device_request((interf, index), player::OPEN_MODE);
            let reply = self.call(link, open).await?;
            if !granted(&reply, player::OPEN_MODE) {
                tracing::warn!(
                    port = self.port,
                    "could not resubscribe {interf}:{index} after reconnecting"
                );
            }
        }
        Ok(())
    }
}

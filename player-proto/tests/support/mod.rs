//! Shared by the protocol's integration tests: a raw Player client over a blocking socket,
//! speaking bytes exactly as written, with every read bounded in time.

#![allow(dead_code)]

pub mod annotated;
pub mod captures;
pub mod served_robots;
pub mod sessions;
pub mod test_server;

use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::Duration;

use player_proto::message::{Body, Message};
use player_proto::wire::{Banner, DevAddr, FrameDecoder, MsgType};

pub struct RawClient {
    pub stream: TcpStream,
    frames: FrameDecoder,
    pub banner: Banner,
}

impl RawClient {
    pub fn connect(port: u16) -> RawClient {
        let stream = TcpStream::connect(("127.0.0.1", port)).expect("connect");
        stream
            .set_read_timeout(Some(Duration::from_secs(3)))
            .unwrap();
        let mut client = RawClient {
            stream,
            frames: FrameDecoder::default(),
            banner: Banner::new("0.0").unwrap(),
        };
        let mut raw = [0u8; 32];
        client.stream.read_exact(&mut raw).expect("banner");
        client.banner = Banner::parse(&raw).expect("a Player banner");
        client
    }

    pub fn send(&mut self, message: &Message) {
        self.stream.write_all(&message.to_bytes()).unwrap();
    }

    pub fn send_raw(&mut self, bytes: &[u8]) {
        self.stream.write_all(bytes).unwrap();
    }

    pub fn request(&mut self, addr: DevAddr, subtype: u8, body: Body) -> Message {
        self.send(&Message::new(addr, MsgType::Req, subtype, body));
        self.next()
    }

    /// The next message; panics after the read timeout.
    pub fn next(&mut self) -> Message {
        self.try_next().expect("a message before the timeout")
    }

    /// The next message, or `None` if nothing came within the read timeout or the peer closed.
    pub fn try_next(&mut self) -> Option<Message> {
        loop {
            if let Some(frame) = self.frames.next_frame().expect("good framing") {
                return Some(Message::decode(frame.header, frame.body).expect("decodable"));
            }
            let mut buf = [0u8; 65536];
            match self.stream.read(&mut buf) {
                Ok(0) | Err(_) => return None,
                Ok(n) => self.frames.extend(&buf[..n]),
            }
        }
    }

    pub fn set_timeout(&self, timeout: Duration) {
        self.stream.set_read_timeout(Some(timeout)).unwrap();
    }
}

//! (Written by a teammate against another draft of the server; ported to this one.)
//!
//! The strongest check of the server: replay the client side of real Player 3.1 + Stage
//! sessions (the repository's `captures/`) against a server configured with the same devices,
//! and compare what it sends with what the real server sent.
//!
//! Devices and driver names come from the captured device list and DRIVERINFO replies. Device
//! replies (geometry, configuration, NACKs) are the captured ones, served by a device that
//! answers from that list: what is tested is the server's routing, ordering, addressing and its
//! own `player`-interface answers. DATA the real server sent is published just before the
//! client message after which it was received, so PULL rounds must put the ACK first, then the
//! data, then the SYNCH, exactly as the real server did.

mod support;

use std::collections::{HashMap, VecDeque};
use std::time::Duration;

use bytes::Bytes;
use player_proto::capture::{Direction, parse_capture, stream};
use player_proto::interfaces::player::{self, DevList, Player};
use player_proto::server::{Device, Reply, Server, ServerConfig};
use player_proto::wire::{DevAddr, FrameDecoder};
use player_proto::{Body, Interface, Message, MsgType};
use support::RawClient;
use support::captures::capture;

/// The concatenated bytes of one direction.
fn direction(name: &str, dir: &str) -> Vec<u8> {
    let text = std::fs::read_to_string(capture(name)).expect("capture file");
    let chunks = parse_capture(&text).expect("capture lines");
    stream(
        &chunks,
        if dir == "s2c" {
            Direction::ServerToClient
        } else {
            Direction::ClientToServer
        },
    )
}

/// Messages of one direction, each with its raw bytes.
fn messages(name: &str, dir: &str) -> Vec<(Message, Bytes)> {
    let mut bytes = direction(name, dir);
    if dir == "s2c" {
        bytes.drain(..32);
    }
    let mut frames = FrameDecoder::default();
    frames.extend(&bytes);
    let mut out = Vec::new();
    let mut at = 0;
    while let Some(frame) = frames.next_frame().expect("capture framing") {
        let len = 40 + frame.body.len();
        let raw = Bytes::copy_from_slice(&bytes[at..at + len]);
        at += len;
        out.push((Message::decode(frame.header, frame.body).unwrap(), raw));
    }
    assert_eq!(frames.buffered(), 0, "{name} {dir} ends mid-message");
    out
}

/// The device list of a port, with driver names, as the real server reported them.
fn served_devices(devlist_capture: &str) -> Vec<(DevAddr, String)> {
    let s2c = messages(devlist_capture, "s2c");
    let devices = s2c
        .iter()
        .find_map(|(m, _)| match &m.body {
            Body::Player(Player::DevList(DevList { devices })) => Some(devices.clone()),
            _ => None,
        })
        .expect("a devlist reply");
    let names: HashMap<(Interface, u16), String> = s2c
        .iter()
        .filter_map(|(m, _)| match &m.body {
            Body::Player(Player::DriverInfo(info)) => Some((
                (info.addr.interf, info.addr.index),
                info.driver_name.as_str().trim_end_matches('\0').to_string(),
            )),
            _ => None,
        })
        .collect();
    devices
        .into_iter()
        .map(|d| (d, names[&(d.interf, d.index)].clone()))
        .collect()
}

/// Answers requests with the replies the real driver gave, in order.
struct Recorded {
    name: String,
    replies: VecDeque<(u8, MsgType, Body)>,
}

impl Device for Recorded {
    fn driver_name(&self) -> &str {
        &self.name
    }
    fn on_request(&mut self, request: &Message) -> Reply {
        match self.replies.front() {
            Some((subtype, _, _)) if *subtype == request.header.subtype => {
                match self.replies.pop_front() {
                    Some((_, MsgType::Ack, body)) => Reply::Ack(body),
                    _ => Reply::Nack,
                }
            }
            _ => Reply::Nack,
        }
    }
}

/// Host and port out of the way: what remains must be identical.
fn normalized(m: &Message, port: u32, our_port: u32) -> (u32, u32, u16, u16, MsgType, u8, Body) {
    let fix = |a: &DevAddr| DevAddr {
        robot: if a.robot == port { our_port } else { a.robot },
        ..*a
    };
    let mut body = m.body.clone();
    match &mut body {
        Body::Player(Player::DevList(list)) => list.devices.iter_mut().for_each(|d| *d = fix(d)),
        Body::Player(Player::DriverInfo(info)) => info.addr = fix(&info.addr),
        Body::Player(Player::Device(req)) => req.addr = fix(&req.addr),
        _ => {}
    }
    let a = fix(&m.header.addr);
    (
        a.host,
        a.robot,
        a.interf.0,
        a.index,
        m.header.msg_type,
        m.header.subtype,
        body,
    )
}

fn replay(capture: &str, devlist_capture: &str, port: u32) {
    let c2s = messages(capture, "c2s");
    let s2c: Vec<Message> = messages(capture, "s2c")
        .into_iter()
        .map(|(m, _)| m)
        .collect();
    let mut config = ServerConfig::default();
    let robot = config.robot(0);
    for (addr, name) in served_devices(devlist_capture) {
        let replies = s2c
            .iter()
            .filter(|m| m.header.msg_type.is_reply() && m.header.addr.same_device(&addr))
            .map(|m| (m.header.subtype, m.header.msg_type, m.body.clone()))
            .collect();
        config.device(
            robot,
            DevAddr::local(addr.interf, addr.index),
            Recorded { name, replies },
        );
    }
    let server = Server::start(config).unwrap();
    let our_port = u32::from(server.port(robot));
    let publisher = server.publisher();
    let mut client = RawClient::connect(server.port(robot));

    let mut next = 0; // first s2c message not yet accounted for
    let mut compared = 0;
    for (sent, raw) in &c2s {
        let h = sent.header;
        let mut end = next;
        if h.msg_type == MsgType::Req {
            // Up to the reply to this request, then, for a data request, its round.
            match s2c[next..].iter().position(|m| {
                m.header.msg_type.is_reply()
                    && m.header.addr.same_device(&h.addr)
                    && m.header.subtype == h.subtype
            }) {
                Some(at) => end = next + at + 1,
                None => panic!("{capture}: no captured reply to {h}"),
            }
            if h.addr.interf == Interface::PLAYER && h.subtype == player::REQ_DATA {
                let synch = s2c[end..]
                    .iter()
                    .position(|m| m.header.msg_type == MsgType::Synch);
                if let Some(at) = synch {
                    end += at + 1;
                }
            }
        }
        let expected = &s2c[next..end];
        next = end;
        for m in expected
            .iter()
            .filter(|m| m.header.msg_type == MsgType::Data)
        {
            let addr = DevAddr {
                robot: our_port,
                ..m.header.addr
            };
            publisher.publish(addr, m.header.subtype, m.body.clone(), m.header.timestamp);
        }
        client.send_raw(raw);
        for want in expected {
            let got = client.next();
            assert_eq!(
                normalized(&got, port, our_port),
                normalized(want, port, our_port),
                "{capture}: reply {compared} after {h}"
            );
            if want.header.msg_type == MsgType::Data {
                assert_eq!(got.header.timestamp, want.header.timestamp);
            }
            compared += 1;
        }
    }
    client.set_timeout(Duration::from_millis(100));
    assert!(
        client.try_next().is_none(),
        "{capture}: the server sent more than the real one"
    );
    assert!(compared > 0);
    eprintln!(
        "{capture}: {compared} of {} server messages matched",
        s2c.len()
    );
}

#[test]
fn devlist_and_driverinfo_match_the_real_server() {
    replay("devlist_driverinfo.jsonl", "devlist_driverinfo.jsonl", 6665);
}

#[test]
fn devlist_and_driverinfo_on_the_second_port_match() {
    replay(
        "devlist_driverinfo_port6666.jsonl",
        "devlist_driverinfo_port6666.jsonl",
        6666,
    );
}

#[test]
fn pull_rounds_match_the_real_server() {
    replay(
        "pull_position2d_laser.jsonl",
        "devlist_driverinfo.jsonl",
        6665,
    );
}

#[test]
fn geometry_and_config_requests_match_the_real_server() {
    replay("geom_config.jsonl", "devlist_driverinfo.jsonl", 6665);
}

#[test]
fn nacks_and_simulation_requests_match_the_real_server() {
    replay(
        "nack_and_simulation.jsonl",
        "devlist_driverinfo.jsonl",
        6665,
    );
}

#[test]
fn push_sessions_match_the_real_server() {
    replay("laser_push.jsonl", "devlist_driverinfo.jsonl", 6665);
    replay(
        "multi_robot_one_port.jsonl",
        "devlist_driverinfo.jsonl",
        6665,
    );
    replay("position2d_move.jsonl", "devlist_driverinfo.jsonl", 6665);
}

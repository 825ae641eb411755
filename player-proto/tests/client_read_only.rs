//! A read-only client (an observer) against a server that records every message it receives:
//! commands and configuration requests are refused in the client and never reach the socket,
//! while everything an observer needs still works.

use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use player_proto::client::{Client, ClientOptions, RequestError};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::player::{self, DevList, DeviceReq, DriverInfo, Player};
use player_proto::interfaces::position2d::{
    self, Position2d, Position2dCmdVel, Position2dGeometry,
};
use player_proto::message::{Body, Message};
use player_proto::wire::{Banner, DevAddr, FrameDecoder, Interface, MsgType, PlayerString};

/// What the recording server received: type, interface and subtype of each message.
type Received = Arc<Mutex<Vec<(MsgType, Interface, u8)>>>;

const BASE: DevAddr = DevAddr {
    host: 0x0100_007f,
    robot: 6665,
    interf: Interface::POSITION2D,
    index: 0,
};

fn next_message(stream: &mut TcpStream, frames: &mut FrameDecoder) -> Option<Message> {
    loop {
        if let Ok(Some(frame)) = frames.next_frame() {
            return Message::decode(frame.header, frame.body).ok();
        }
        let mut buf = [0u8; 4096];
        match stream.read(&mut buf) {
            Ok(0) | Err(_) => return None,
            Ok(n) => frames.extend(&buf[..n]),
        }
    }
}

/// The answer a server with one position2d gives; `None` for a command (no reply).
fn answer(request: &Message) -> Option<Message> {
    let h = request.header;
    if h.msg_type != MsgType::Req {
        return None;
    }
    let body = match (h.addr.interf, h.subtype) {
        (Interface::PLAYER, player::REQ_DEVLIST) => Body::Player(Player::DevList(DevList {
            devices: vec![BASE],
        })),
        (Interface::PLAYER, player::REQ_DRIVERINFO) => {
            Body::Player(Player::DriverInfo(DriverInfo {
                addr: BASE,
                driver_name: PlayerString::new("recorder"),
            }))
        }
        (Interface::PLAYER, player::REQ_DEV) => match &request.body {
            Body::Player(Player::Device(asked)) => Body::Player(Player::Device(DeviceReq {
                addr: BASE,
                access: asked.access,
                driver_name: PlayerString::new("recorder"),
            })),
            _ => Body::Empty,
        },
        (Interface::POSITION2D, position2d::REQ_GET_GEOM) => {
            Body::Position2d(Position2d::Geometry(Position2dGeometry::default()))
        }
        _ => Body::Empty,
    };
    Some(Message::new(h.addr, MsgType::Ack, h.subtype, body))
}

/// A server for one connection that answers like a robot with a base and records everything.
fn recording_server() -> (u16, Received) {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    let received = Received::default();
    let log = received.clone();
    std::thread::spawn(move || {
        let Ok((mut stream, _)) = listener.accept() else {
            return;
        };
        stream
            .write_all(&Banner::new("3.1.1-dev").unwrap().to_bytes())
            .unwrap();
        let mut frames = FrameDecoder::default();
        while let Some(message) = next_message(&mut stream, &mut frames) {
            let h = message.header;
            log.lock()
                .unwrap()
                .push((h.msg_type, h.addr.interf, h.subtype));
            if let Some(reply) = answer(&message)
                && stream.write_all(&reply.to_bytes()).is_err()
            {
                return;
            }
        }
    });
    (port, received)
}

fn observer() -> ClientOptions {
    ClientOptions {
        read_only: true,
        request_timeout: Duration::from_secs(5),
        ..ClientOptions::default()
    }
}

#[test]
fn a_read_only_client_never_sends_a_command_or_a_configuration_request() {
    let (port, received) = recording_server();
    let client = Client::connect("127.0.0.1", port, observer()).expect("connect");
    assert!(client.is_read_only());
    let base = client.position2d(0);
    base.subscribe().expect("an observer subscribes");
    // Reading the geometry is what a viewer needs; it is no configuration.
    base.geometry().expect("an observer reads the geometry");

    base.set_velocity(0.5, 0.0, 0.2);
    base.go_to(Pose2d::new(1.0, 1.0, 0.0));
    let drive = Position2d::Velocity(Position2dCmdVel {
        vel: Pose2d::new(0.5, 0.0, 0.0),
        state: 1,
    });
    assert!(matches!(
        client.try_command(base.addr(), drive),
        Err(RequestError::ReadOnly(_))
    ));
    assert!(matches!(
        base.set_motor_power(true),
        Err(RequestError::ReadOnly(_))
    ));
    let reset = client.request(base.addr(), position2d::REQ_RESET_ODOM, Body::Empty);
    assert!(matches!(reset, Err(RequestError::ReadOnly(_))));

    // The connection is ordered: once this ACK is back, the server has read everything the
    // client sent before it.
    base.unsubscribe().expect("an observer unsubscribes");
    let received = received.lock().unwrap().clone();
    assert!(
        received.iter().all(|&(kind, _, _)| kind == MsgType::Req),
        "only requests reached the server: {received:?}"
    );
    let to_the_base: Vec<_> = received
        .iter()
        .filter(|(_, interf, _)| *interf == Interface::POSITION2D)
        .collect();
    assert_eq!(
        to_the_base,
        [&(
            MsgType::Req,
            Interface::POSITION2D,
            position2d::REQ_GET_GEOM
        )],
        "the geometry request is the only one the base saw"
    );
    let subscriptions = received
        .iter()
        .filter(|(_, interf, subtype)| *interf == Interface::PLAYER && *subtype == player::REQ_DEV)
        .count();
    assert_eq!(subscriptions, 2, "subscribe and unsubscribe went out");
}

#[test]
fn a_client_that_is_not_read_only_still_commands() {
    let (port, received) = recording_server();
    let client = Client::connect("127.0.0.1", port, ClientOptions::default()).expect("connect");
    let base = client.position2d(0);
    base.set_velocity(0.5, 0.0, 0.2);
    base.set_motor_power(true).expect("ACKed");
    let received = received.lock().unwrap().clone();
    assert!(received.contains(&(MsgType::Cmd, Interface::POSITION2D, 1)));
}

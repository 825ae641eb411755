//! A connection's data is written by the publishing thread when the socket takes it and by
//! the connection's writer task when it does not (a client that stops reading, a small send
//! buffer), or by the writer task alone (the default): either way every message arrives
//! whole, once, in the order it was published.

mod support;

use std::time::Duration;

use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::interfaces::player::{self, DeviceReq, Player};
use player_proto::message::Body;
use player_proto::server::{Server, ServerConfig};
use player_proto::wire::{DevAddr, Interface, MsgType, PlayerString};
use support::RawClient;
use support::served_robots::Laser0;

/// A laser on a server whose connections have a small send buffer.
fn server(publisher_writes: bool) -> (Server, DevAddr) {
    let mut config = ServerConfig::default();
    config.send_buffer = Some(4096);
    config.publisher_writes = publisher_writes;
    let robot = config.robot(0);
    config.device(robot, "laser:0".parse().unwrap(), Laser0);
    let server = Server::start(config).unwrap();
    let addr = DevAddr {
        robot: u32::from(server.port(0)),
        ..DevAddr::local(Interface::LASER, 0)
    };
    (server, addr)
}

/// A client subscribed to the laser.
fn subscriber(server: &Server) -> RawClient {
    let mut client = RawClient::connect(server.port(0));
    let req = DeviceReq {
        addr: "laser:0".parse().unwrap(),
        access: player::OPEN_MODE,
        driver_name: PlayerString::default(),
    };
    let ack = client.request(
        DevAddr::local(Interface::PLAYER, 0),
        player::REQ_DEV,
        Body::Player(Player::Device(req)),
    );
    assert_eq!(ack.header.msg_type, MsgType::Ack);
    client
}

/// A scan of 1 000 readings, about 4 KiB on the wire.
fn scan(id: u32) -> Body {
    Body::Laser(Laser::Scan(LaserScan {
        ranges: vec![2.5; 1000],
        max_range: 8.0,
        id,
        ..LaserScan::default()
    }))
}

fn scan_id(body: &Body) -> u32 {
    match body {
        Body::Laser(Laser::Scan(s)) => s.id,
        other => panic!("expected a scan, got {other:?}"),
    }
}

#[test]
fn a_client_that_does_not_read_gets_every_message_in_order_when_it_does() {
    for publisher_writes in [true, false] {
        does_not_read_then_reads(publisher_writes);
    }
}

fn does_not_read_then_reads(publisher_writes: bool) {
    let (server, addr) = server(publisher_writes);
    let mut client = subscriber(&server);
    // About 1.6 MB while the client reads nothing: far more than the socket buffers hold,
    // so most of it waits for the writer task.
    let publisher = server.publisher();
    for id in 1..=400 {
        assert_eq!(publisher.publish(addr, 1, scan(id), 0.0), 1);
    }
    std::thread::sleep(Duration::from_millis(200));
    for id in 1..=400 {
        assert_eq!(scan_id(&client.next().body), id);
    }
    // And the connection still answers: a request's reply comes after all of it.
    let reply = client.request(
        DevAddr::local(Interface::PLAYER, 0),
        player::REQ_DEVLIST,
        Body::Empty,
    );
    assert_eq!(reply.header.msg_type, MsgType::Ack);
}

#[test]
fn publishers_on_several_threads_never_interleave_their_bytes() {
    for publisher_writes in [true, false] {
        several_publishers(publisher_writes);
    }
}

fn several_publishers(publisher_writes: bool) {
    let (server, addr) = server(publisher_writes);
    let mut client = subscriber(&server);
    let threads: Vec<_> = (0..3u32)
        .map(|t| {
            let publisher = server.publisher();
            std::thread::spawn(move || {
                for k in 0..200 {
                    publisher.publish(addr, 1, scan(t * 1000 + k), 0.0);
                }
            })
        })
        .collect();
    let mut next = [0u32; 3];
    for _ in 0..600 {
        // Whole messages only: `next` panics on broken framing or an undecodable body.
        let id = scan_id(&client.next().body);
        let (t, k) = ((id / 1000) as usize, id % 1000);
        assert_eq!(
            k, next[t],
            "thread {t}'s scans in the order it published them"
        );
        next[t] += 1;
    }
    for thread in threads {
        thread.join().unwrap();
    }
}

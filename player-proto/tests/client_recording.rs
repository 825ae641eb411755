//! A client with a recorder's tap against the server module over real TCP: the file holds the
//! whole session — the connection, the banner, every request sent and every message received,
//! bytes as on the wire — and the close.

use std::sync::Arc;
use std::sync::mpsc;
use std::time::Duration;

use player_proto::capture::Direction;
use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::interfaces::player;
use player_proto::message::{Body, Message};
use player_proto::recording::{self, Event, Recorder};
use player_proto::server::{Device, Server, ServerConfig};
use player_proto::wire::{DevAddr, Interface, MsgType};

struct Laser0;
impl Device for Laser0 {
    fn driver_name(&self) -> &str {
        "sicklms200"
    }
}

const WAIT: Duration = Duration::from_secs(10);
const SCANS: u32 = 5;

fn scan(id: u32) -> Body {
    Body::Laser(Laser::Scan(LaserScan {
        ranges: vec![1.5; 361],
        max_range: 8.0,
        id,
        ..LaserScan::default()
    }))
}

#[test]
fn a_recorded_session_holds_every_message_as_it_crossed_the_wire() {
    let mut config = ServerConfig::default();
    let robot = config.robot(0);
    config.device(robot, "laser:0".parse().unwrap(), Laser0);
    let server = Server::start(config).unwrap();
    let port = server.port(0);

    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("session.prec");
    let recorder = Recorder::create(&path).unwrap();
    let (stored, arrivals) = mpsc::channel();
    let options = ClientOptions {
        tap: Some(recorder.tap()),
        replace_old_data: false,
        notifier: Some(Arc::new(move || {
            let _ = stored.send(());
        })),
        ..ClientOptions::default()
    };
    let mut client = Client::connect("127.0.0.1", port, options).unwrap();
    client.laser(0).subscribe().unwrap();
    let mut at: DevAddr = "laser:0".parse().unwrap();
    at.robot = u32::from(port);
    for id in 1..=SCANS {
        let subtype = Laser::DATA_SCAN.subtype();
        server
            .publisher()
            .publish(at, subtype, scan(id), f64::from(id));
    }
    // The notifier also runs on changes of connection state: count the scans kept.
    while client.stats(at).messages < u64::from(SCANS) {
        arrivals.recv_timeout(WAIT).expect("every scan arrives");
    }
    client.close();
    let stats = recorder.finish().unwrap();
    assert_eq!(stats.lost(), 0, "{stats:?}");
    assert!(stats.error.is_none());

    let records: Vec<_> = recording::open(&path)
        .unwrap()
        .collect::<Result<_, _>>()
        .unwrap();
    assert_eq!(records.len() as u64, stats.written);
    assert!(matches!(
        &records[0].event,
        Event::Connection { host, port: p } if host == "127.0.0.1" && *p == port
    ));
    assert!(
        matches!(records[1].event, Event::Opened { banner } if banner.starts_with(b"Player v.3"))
    );
    assert!(matches!(
        &records.last().unwrap().event,
        Event::Closed { why } if why == "client closed"
    ));
    assert!(records.windows(2).all(|w| w[0].time_ns <= w[1].time_ns));

    let messages: Vec<_> = records
        .iter()
        .filter_map(|r| match &r.event {
            Event::Message {
                direction,
                header,
                body,
            } => Some((*direction, *header, body.clone())),
            _ => None,
        })
        .collect();
    let sent = |subtype| {
        messages.iter().any(|(d, h, _)| {
            *d == Direction::ClientToServer
                && h.addr.interf == Interface::PLAYER
                && h.msg_type == MsgType::Req
                && h.subtype == subtype
        })
    };
    assert!(
        sent(player::REQ_DEVLIST),
        "the device list request is recorded"
    );
    assert!(sent(player::REQ_DEV), "the subscription is recorded");

    let scans: Vec<_> = messages
        .iter()
        .filter(|(d, h, _)| *d == Direction::ServerToClient && h.msg_type == MsgType::Data)
        .collect();
    assert_eq!(scans.len(), SCANS as usize);
    for ((_, header, body), id) in scans.into_iter().zip(1..) {
        let decoded = Message::decode(*header, body.clone()).unwrap();
        assert_eq!(decoded.body, scan(id));
        assert_eq!(header.timestamp, f64::from(id));
        assert_eq!(header.addr.robot, u32::from(port));
    }
}

//! Messages per second through the client from a server pushing 361-beam laser scans as fast
//! as a socket takes them, against two baselines measured in the same run on the same bytes:
//! a bare socket reader that only frames, and one that frames and decodes.
//!
//! `cargo bench -p player-proto --bench client_throughput`

use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::interfaces::player::{self, DevList, DeviceReq, DriverInfo, Player};
use player_proto::message::{Body, Message};
use player_proto::wire::{Banner, DevAddr, FrameDecoder, Interface, MsgType, Opaque, PlayerString};

const MESSAGES: u64 = 200_000;

fn scan_bytes(batch: usize) -> Vec<u8> {
    let addr = DevAddr {
        host: 0x0100_007f,
        robot: 6665,
        interf: Interface::LASER,
        index: 0,
    };
    let scan = LaserScan {
        min_angle: -1.57,
        max_angle: 1.57,
        resolution: 0.0087,
        max_range: 8.0,
        ranges: (0..361).map(|i| 1.0 + (i % 50) as f32 * 0.1).collect(),
        intensity: Opaque::from(vec![1u8; 361]),
        id: 0,
    };
    let one = Message::typed(addr, MsgType::Data, Laser::Scan(scan)).to_bytes();
    one.iter()
        .copied()
        .cycle()
        .take(one.len() * batch)
        .collect()
}

/// Answers a client's handshake and one subscription, then streams scans until `count` sent.
fn serve(mut stream: TcpStream, count: u64, handshake: bool) {
    stream.set_nodelay(true).ok();
    stream
        .write_all(&Banner::new("3.1.1-dev").unwrap().to_bytes())
        .unwrap();
    if handshake {
        let laser = DevAddr {
            host: 0x0100_007f,
            robot: 6665,
            interf: Interface::LASER,
            index: 0,
        };
        let mut frames = FrameDecoder::default();
        let mut buf = vec![0u8; 65536];
        'handshake: loop {
            let n = stream.read(&mut buf).unwrap();
            frames.extend(&buf[..n]);
            while let Some(frame) = frames.next_frame().unwrap() {
                let request = Message::decode(frame.header, frame.body).unwrap();
                let body = match request.header.subtype {
                    player::REQ_DEVLIST => Body::Player(Player::DevList(DevList {
                        devices: vec![laser],
                    })),
                    player::REQ_DRIVERINFO => Body::Player(Player::DriverInfo(DriverInfo {
                        addr: laser,
                        driver_name: PlayerString::new("bench"),
                    })),
                    player::REQ_DEV => Body::Player(Player::Device(DeviceReq {
                        addr: laser,
                        access: 1,
                        driver_name: PlayerString::new("bench"),
                    })),
                    _ => Body::Empty,
                };
                let subscribed = request.header.subtype == player::REQ_DEV;
                stream
                    .write_all(
                        &Message::new(
                            request.header.addr,
                            MsgType::Ack,
                            request.header.subtype,
                            body,
                        )
                        .to_bytes(),
                    )
                    .unwrap();
                if subscribed {
                    break 'handshake;
                }
            }
        }
    }
    let batch = 1000;
    let bytes = scan_bytes(batch);
    let mut sent = 0;
    while sent < count {
        if stream.write_all(&bytes).is_err() {
            return;
        }
        sent += batch as u64;
    }
}

fn listener() -> (TcpListener, u16) {
    let l = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = l.local_addr().unwrap().port();
    (l, port)
}

/// A reader that frames (and optionally decodes) and does nothing else.
fn bare(decode: bool) -> f64 {
    let (l, port) = listener();
    std::thread::spawn(move || serve(l.accept().unwrap().0, MESSAGES, false));
    let mut stream = TcpStream::connect(("127.0.0.1", port)).unwrap();
    let mut frames = FrameDecoder::default();
    let mut buf = vec![0u8; 1 << 20];
    let mut seen = 0u64;
    let mut started = None;
    let _ = frames.take_banner();
    while seen < MESSAGES {
        let n = stream.read(&mut buf).unwrap();
        assert!(n > 0, "server closed early");
        started.get_or_insert_with(Instant::now);
        frames.extend(&buf[..n]);
        if frames.offset() == 0 {
            let _ = frames.take_banner();
        }
        while let Some(frame) = frames.next_frame().unwrap() {
            if decode {
                std::hint::black_box(Message::decode(frame.header, frame.body).unwrap());
            }
            seen += 1;
        }
    }
    seen as f64 / started.unwrap().elapsed().as_secs_f64()
}

/// The full client: robot thread, decoding, newest-data store, notifier.
fn through_client() -> f64 {
    let (l, port) = listener();
    std::thread::spawn(move || serve(l.accept().unwrap().0, MESSAGES + 1000, true));
    let count = Arc::new(AtomicU64::new(0));
    let counter = count.clone();
    let options = ClientOptions {
        replace_old_data: false,
        notifier: Some(Arc::new(move || {
            counter.fetch_add(1, Ordering::Relaxed);
        })),
        ..ClientOptions::default()
    };
    let client = Client::connect("127.0.0.1", port, options).unwrap();
    client.laser(0).subscribe().unwrap();
    while count.load(Ordering::Relaxed) == 0 {
        std::thread::sleep(Duration::from_micros(100));
    }
    let started = Instant::now();
    let first = count.load(Ordering::Relaxed);
    while count.load(Ordering::Relaxed) < first + MESSAGES - 2000 {
        std::thread::sleep(Duration::from_micros(200));
    }
    (count.load(Ordering::Relaxed) - first) as f64 / started.elapsed().as_secs_f64()
}

fn main() {
    // `cargo test` runs benches with --bench absent; only measure when asked.
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    let frame_only = bare(false);
    let decode = bare(true);
    let client = through_client();
    println!("361-beam laser scans over a loopback socket, {MESSAGES} messages:");
    println!(
        "  bare socket, framing only:   {:>10.0} msg/s  (1.00)",
        frame_only
    );
    println!(
        "  bare socket, frame + decode: {:>10.0} msg/s  ({:.2})",
        decode,
        decode / frame_only
    );
    println!(
        "  through the client:          {:>10.0} msg/s  ({:.2})",
        client,
        client / frame_only
    );
}

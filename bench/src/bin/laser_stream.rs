//! A 361-beam laser stream pushed flat out, and the Rust client's read rate on it: the
//! baseline for player3's `.read()` (python/benches/read_rate.py runs both in one run).
//!
//! `laser_stream serve` prints its port, then answers each connection's handshake and
//! subscription and pushes scans as fast as the socket takes them, until killed.
//! `laser_stream read PORT SECONDS` reads it the way player3's `.read()` does — wait for a
//! reading newer than the last, take a copy of its scan — and prints reads per second.

use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::interfaces::player::{self, DevList, DeviceReq, DriverInfo, Player};
use player_proto::message::{Body, Message};
use player_proto::wire::{Banner, DevAddr, FrameDecoder, Interface, MsgType, Opaque, PlayerString};

fn laser_addr(port: u16) -> DevAddr {
    DevAddr {
        host: 0x0100_007f,
        robot: u32::from(port),
        interf: Interface::LASER,
        index: 0,
    }
}

/// A thousand scans back to back, each stamped with its own time so every one is new.
fn scans(port: u16, first: usize) -> Vec<u8> {
    let mut out = Vec::new();
    for n in first..first + 1000 {
        let scan = LaserScan {
            min_angle: -1.57,
            max_angle: 1.57,
            resolution: 0.008_722,
            max_range: 8.0,
            ranges: (0..361)
                .map(|i| 1.0 + ((i + n) % 50) as f32 * 0.1)
                .collect(),
            intensity: Opaque::from(vec![1u8; 361]),
            id: n as u32,
        };
        let mut message = Message::typed(laser_addr(port), MsgType::Data, Laser::Scan(scan));
        message.header.timestamp = n as f64 * 1e-3;
        out.extend_from_slice(&message.to_bytes());
    }
    out
}

/// Answers the handshake and the subscription, then pushes until the client goes away.
fn push(mut stream: TcpStream, port: u16) -> Result<()> {
    stream.set_nodelay(true)?;
    stream.write_all(&Banner::new("3.1.1-dev")?.to_bytes())?;
    let laser = laser_addr(port);
    let mut frames = FrameDecoder::default();
    let mut buf = vec![0u8; 65536];
    'handshake: loop {
        let n = stream.read(&mut buf)?;
        if n == 0 {
            return Ok(());
        }
        frames.extend(&buf[..n]);
        while let Some(frame) = frames.next_frame()? {
            let request = Message::decode(frame.header, frame.body)?;
            let body = match request.header.subtype {
                player::REQ_DEVLIST => Body::Player(Player::DevList(DevList {
                    devices: vec![laser],
                })),
                player::REQ_DRIVERINFO => Body::Player(Player::DriverInfo(DriverInfo {
                    addr: laser,
                    driver_name: PlayerString::new("laser_stream"),
                })),
                player::REQ_DEV => Body::Player(Player::Device(DeviceReq {
                    addr: laser,
                    access: 1,
                    driver_name: PlayerString::new("laser_stream"),
                })),
                _ => Body::Empty,
            };
            let subscribed = request.header.subtype == player::REQ_DEV;
            let ack = Message::new(
                request.header.addr,
                MsgType::Ack,
                request.header.subtype,
                body,
            );
            stream.write_all(&ack.to_bytes())?;
            if subscribed {
                break 'handshake;
            }
        }
    }
    // Requests after the subscription (replace rules, data mode) are acknowledged by nobody:
    // the client does not wait for them before reading.
    let mut first = 0;
    loop {
        stream.write_all(&scans(port, first))?;
        first += 1000;
    }
}

fn serve() -> Result<()> {
    let listener = TcpListener::bind("127.0.0.1:0")?;
    let port = listener.local_addr()?.port();
    println!("{port}");
    std::io::stdout().flush()?;
    for stream in listener.incoming() {
        let stream = stream?;
        std::thread::spawn(move || push(stream, port));
    }
    Ok(())
}

/// Reads like `.read()`: waits (on the client's notifier) for a scan newer than the last.
fn read(port: u16, seconds: f64) -> Result<f64> {
    let wake = Arc::new((Mutex::new(0u64), Condvar::new()));
    let ring = wake.clone();
    let options = ClientOptions {
        notifier: Some(Arc::new(move || {
            *ring.0.lock().unwrap() += 1;
            ring.1.notify_all();
        })),
        ..ClientOptions::default()
    };
    let client = Client::connect("127.0.0.1", port, options)?;
    let laser = client.laser(0);
    laser.subscribe()?;
    let (mut last, mut reads) = (0u64, 0u64);
    let started = Instant::now();
    let limit = Duration::from_secs_f64(seconds);
    while started.elapsed() < limit {
        let seen = *wake.0.lock().unwrap();
        match laser.scan() {
            Some((scan, stamped)) if stamped.seq > last => {
                last = stamped.seq;
                std::hint::black_box(scan);
                reads += 1;
            }
            _ => {
                let guard = wake.0.lock().unwrap();
                let _ = wake
                    .1
                    .wait_timeout_while(guard, Duration::from_millis(50), |g| *g == seen);
            }
        }
    }
    Ok(reads as f64 / started.elapsed().as_secs_f64())
}

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args
        .iter()
        .map(String::as_str)
        .collect::<Vec<_>>()
        .as_slice()
    {
        ["serve"] => serve(),
        ["read", port, seconds] => {
            let rate = read(
                port.parse().context("PORT")?,
                seconds.parse().context("SECONDS")?,
            )?;
            println!("{rate:.0}");
            Ok(())
        }
        _ => bail!("usage: laser_stream serve | laser_stream read PORT SECONDS"),
    }
}

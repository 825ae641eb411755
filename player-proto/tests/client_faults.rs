//! The client against servers that misbehave: stalls, garbage, lying sizes, half messages,
//! replies to nothing, unknown interfaces. No panic, no hang; it recovers or says why not.

use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use player_proto::client::{Backoff, Client, ClientOptions, ConnectionState};
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::interfaces::player::{self, DevList, DeviceReq, DriverInfo, Player};
use player_proto::message::{Body, Message};
use player_proto::wire::{Banner, DevAddr, FrameDecoder, Interface, MsgType, PlayerString};

fn quick() -> ClientOptions {
    ClientOptions {
        connect_timeout: Duration::from_millis(500),
        request_timeout: Duration::from_millis(500),
        backoff: Backoff {
            initial: Duration::from_millis(50),
            max: Duration::from_millis(100),
            max_attempts: None,
        },
        ..ClientOptions::default()
    }
}

fn read_message(stream: &mut TcpStream, frames: &mut FrameDecoder) -> Option<Message> {
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

/// Answers the client's handshake and subscriptions like a server with one laser.
fn handshake(stream: &mut TcpStream, frames: &mut FrameDecoder, subscriptions: usize) {
    let laser = DevAddr {
        host: 0x0100_007f,
        robot: 6665,
        interf: Interface::LASER,
        index: 0,
    };
    let mut answered_subscriptions = 0;
    while let Some(request) = read_message(stream, frames) {
        let body = match (&request.header.subtype, &request.body) {
            (&player::REQ_DEVLIST, _) => Body::Player(Player::DevList(DevList {
                devices: vec![laser],
            })),
            (&player::REQ_DRIVERINFO, _) => Body::Player(Player::DriverInfo(DriverInfo {
                addr: laser,
                driver_name: PlayerString::new("fake"),
            })),
            (&player::REQ_DEV, _) => {
                answered_subscriptions += 1;
                Body::Player(Player::Device(DeviceReq {
                    addr: laser,
                    access: 1,
                    driver_name: PlayerString::new("fake"),
                }))
            }
            _ => Body::Empty,
        };
        let reply = Message::new(
            request.header.addr,
            MsgType::Ack,
            request.header.subtype,
            body,
        );
        stream.write_all(&reply.to_bytes()).unwrap();
        let done_handshake = request.header.subtype == player::REQ_DRIVERINFO
            || request.header.subtype == player::REQ_DEV;
        if done_handshake && answered_subscriptions >= subscriptions {
            return;
        }
    }
}

/// A server that runs `script` on every connection after the banner and the handshake.
fn scripted(
    script: impl Fn(&mut TcpStream, usize) + Send + Sync + 'static,
) -> (u16, Arc<AtomicUsize>) {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    let connections = Arc::new(AtomicUsize::new(0));
    let count = connections.clone();
    std::thread::spawn(move || {
        for stream in listener.incoming() {
            let Ok(mut stream) = stream else { continue };
            let n = count.fetch_add(1, Ordering::SeqCst);
            stream
                .set_read_timeout(Some(Duration::from_secs(5)))
                .unwrap();
            stream
                .write_all(&Banner::new("3.1.1-dev").unwrap().to_bytes())
                .unwrap();
            let mut frames = FrameDecoder::default();
            // Every test subscribes to the laser right after connecting; a reconnection
            // restores that subscription. Either way one subscription completes the handshake.
            handshake(&mut stream, &mut frames, 1);
            script(&mut stream, n);
        }
    });
    (port, connections)
}

fn scan_bytes() -> Vec<u8> {
    let addr = DevAddr {
        host: 0x0100_007f,
        robot: 6665,
        interf: Interface::LASER,
        index: 0,
    };
    Message::typed(
        addr,
        MsgType::Data,
        Laser::Scan(LaserScan {
            ranges: vec![2.0; 10],
            ..LaserScan::default()
        }),
    )
    .to_bytes()
    .to_vec()
}

fn wait_for(what: &str, timeout: Duration, mut ok: impl FnMut() -> bool) {
    let deadline = Instant::now() + timeout;
    while !ok() {
        assert!(Instant::now() < deadline, "timed out waiting for {what}");
        std::thread::sleep(Duration::from_millis(5));
    }
}

#[test]
fn a_stalled_server_times_out_and_never_hangs_the_handle() {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    std::thread::spawn(move || {
        let mut held = Vec::new();
        for mut stream in listener.incoming().flatten() {
            stream
                .write_all(&Banner::new("3.1.1-dev").unwrap().to_bytes())
                .unwrap();
            held.push(stream); // never answers
        }
    });
    let started = Instant::now();
    assert!(Client::connect("127.0.0.1", port, quick()).is_err());
    assert!(started.elapsed() < Duration::from_secs(3));

    let client = Client::spawn("127.0.0.1", port, quick()).unwrap();
    let started = Instant::now();
    assert!(client.laser(0).geometry().is_err());
    assert!(started.elapsed() < Duration::from_secs(3));
    assert_ne!(client.state(), ConnectionState::Connected);
}

fn recovers_after(misbehaviour: fn(&mut TcpStream)) {
    let (port, connections) = scripted(move |stream, n| {
        if n == 0 {
            misbehaviour(stream);
        } else {
            // Behave: send scans until the client goes.
            let bytes = scan_bytes();
            while stream.write_all(&bytes).is_ok() {
                std::thread::sleep(Duration::from_millis(10));
            }
        }
    });
    let client = Client::connect("127.0.0.1", port, quick()).unwrap();
    client.laser(0).subscribe().unwrap();
    wait_for("a second connection", Duration::from_secs(5), || {
        connections.load(Ordering::SeqCst) >= 2
    });
    wait_for(
        "data from the well-behaved connection",
        Duration::from_secs(5),
        || client.laser(0).scan().is_some(),
    );
    assert_eq!(client.state(), ConnectionState::Connected);
}

#[test]
fn garbage_drops_the_connection_and_the_client_reconnects() {
    recovers_after(|stream| {
        std::thread::sleep(Duration::from_millis(100));
        let _ = stream.write_all(&[0xde; 200]);
    });
}

#[test]
fn a_lying_size_drops_the_connection_and_the_client_reconnects() {
    recovers_after(|stream| {
        std::thread::sleep(Duration::from_millis(100));
        let mut bytes = scan_bytes();
        bytes[36..40].copy_from_slice(&[0x7f, 0xff, 0xff, 0xff]);
        let _ = stream.write_all(&bytes);
        std::thread::sleep(Duration::from_millis(300));
    });
}

#[test]
fn half_a_message_then_close() {
    recovers_after(|stream| {
        std::thread::sleep(Duration::from_millis(100));
        let bytes = scan_bytes();
        let _ = stream.write_all(&bytes[..bytes.len() / 2]);
    });
}

#[test]
fn replies_to_nothing_unknown_interfaces_and_bad_bodies_are_counted_not_fatal() {
    let (port, _) = scripted(|stream, _| {
        std::thread::sleep(Duration::from_millis(100));
        // An ACK nobody asked for.
        let ack = Message::new(
            DevAddr::local(Interface::LASER, 0),
            MsgType::Ack,
            9,
            Body::Empty,
        );
        let _ = stream.write_all(&ack.to_bytes());
        // Data of a plugin interface nobody knows.
        let unknown = Message::new(
            DevAddr::local(Interface(200), 0),
            MsgType::Data,
            1,
            Body::Unknown(vec![1, 2, 3, 4].into()),
        );
        let _ = stream.write_all(&unknown.to_bytes());
        // A scan whose ranges count lies.
        let mut bad = scan_bytes();
        bad[56..64].copy_from_slice(&[0, 0, 4, 0, 0, 0, 4, 0]);
        let _ = stream.write_all(&bad);
        // Then good data.
        let good = scan_bytes();
        while stream.write_all(&good).is_ok() {
            std::thread::sleep(Duration::from_millis(10));
        }
    });
    let client = Client::connect("127.0.0.1", port, quick()).unwrap();
    client.laser(0).subscribe().unwrap();
    wait_for("good data after the bad", Duration::from_secs(5), || {
        client.laser(0).scan().is_some()
    });
    assert_eq!(client.state(), ConnectionState::Connected);
    assert_eq!(
        client.rejected(),
        2,
        "the orphan reply and the undecodable scan"
    );
}

#[test]
fn a_server_that_is_not_player_fails_for_good() {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    std::thread::spawn(move || {
        for mut stream in listener.incoming().flatten() {
            let _ =
                stream.write_all(b"SSH-2.0-OpenSSH_9.2p1 Debian-2\r\n\0\0\0\0\0\0\0\0\0\0\0\0\0\0");
        }
    });
    let err = Client::connect("127.0.0.1", port, quick())
        .err()
        .unwrap()
        .to_string();
    assert!(err.contains("not a Player server"), "{err}");
}

#[test]
fn a_server_that_stalls_after_connecting_is_detected_and_left() {
    let (port, connections) = scripted(|stream, n| {
        if n == 0 {
            // Stall: accept the subscription, then never send a byte again (not even the
            // reply to the liveness probe) until the client gives up on us.
            let mut sink = [0u8; 4096];
            let until = Instant::now() + Duration::from_secs(10);
            while Instant::now() < until {
                match stream.read(&mut sink) {
                    Ok(0) => return,
                    Ok(_) => {}
                    Err(e) if e.kind() == std::io::ErrorKind::WouldBlock => {}
                    Err(e) if e.kind() == std::io::ErrorKind::TimedOut => {}
                    Err(_) => return,
                }
            }
        } else {
            let bytes = scan_bytes();
            while stream.write_all(&bytes).is_ok() {
                std::thread::sleep(Duration::from_millis(10));
            }
        }
    });
    let options = ClientOptions {
        stall_timeout: Some(Duration::from_millis(300)),
        ..quick()
    };
    let client = Client::connect("127.0.0.1", port, options).unwrap();
    client.laser(0).subscribe().unwrap();
    assert_eq!(client.state(), ConnectionState::Connected);
    wait_for("the stall to be noticed", Duration::from_secs(3), || {
        client.last_disconnect().is_some()
    });
    let why = client.last_disconnect().unwrap();
    assert!(why.contains("stalled"), "{why}");
    wait_for(
        "data from the next connection",
        Duration::from_secs(5),
        || client.laser(0).scan().is_some(),
    );
    assert!(connections.load(Ordering::SeqCst) >= 2);
    assert_eq!(client.state(), ConnectionState::Connected);
}

#[test]
fn a_server_that_never_works_is_retried_ever_more_slowly() {
    // Accepts, sends a valid banner, then garbage: every TCP connect succeeds, no session
    // ever works. The wait between attempts must keep growing, not restart at every connect.
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    let connections = Arc::new(AtomicUsize::new(0));
    let count = connections.clone();
    std::thread::spawn(move || {
        for mut stream in listener.incoming().flatten() {
            count.fetch_add(1, Ordering::SeqCst);
            let _ = stream.write_all(&Banner::new("3.1.1-dev").unwrap().to_bytes());
            let _ = stream.write_all(&[0xde; 200]);
        }
    });
    let options = ClientOptions {
        backoff: Backoff {
            initial: Duration::from_millis(20),
            max: Duration::from_secs(60),
            max_attempts: None,
        },
        ..quick()
    };
    let client = Client::spawn("127.0.0.1", port, options).unwrap();
    let fourth = client.wait_for_state(
        Duration::from_secs(10),
        |s| matches!(s, ConnectionState::Reconnecting { attempt } if *attempt >= 4),
    );
    assert!(
        fourth.is_some(),
        "the attempt count should grow across accepted connections, but is {}",
        client.state()
    );
    assert!(connections.load(Ordering::SeqCst) >= 4);
    let why = client.last_disconnect().expect("the reason is kept");
    assert!(why.contains("bad header"), "{why}");
}

/// A failed connect names the first attempt's own reason, not a summary that may be wrong:
/// a host name that does not resolve is not "connection refused".
#[test]
fn a_failed_connect_says_what_went_wrong() {
    let closed = {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        listener.local_addr().unwrap().port()
    };
    let refused = Client::connect("127.0.0.1", closed, quick())
        .err()
        .expect("nobody listens there")
        .to_string();
    assert!(
        refused.starts_with(&format!(
            "cannot reach the Player server at 127.0.0.1:{closed}: "
        )) && refused.to_lowercase().contains("refused"),
        "{refused}"
    );
    // .invalid never resolves (RFC 2606).
    let unknown = Client::connect("robot.invalid", 6665, quick())
        .err()
        .expect("no such host")
        .to_string();
    assert!(
        unknown.starts_with("cannot reach the Player server at robot.invalid:6665: ")
            && !unknown.contains("refused"),
        "{unknown}"
    );
}

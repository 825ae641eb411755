//! The page's WebSocket against bad and heavy clients, over real TCP: garbage, binary and
//! oversized frames, commands for robots that are not there or from an observer, a client
//! that never reads, and hundreds connecting at once — each gets a clear refusal or close,
//! and a well-behaved page beside them keeps its once-a-second rows.

mod support;

use std::time::{Duration, Instant};

use futures_util::{SinkExt, StreamExt};
use player_proto::server::Commanders;
use serde_json::Value;
use support::{Front, robot_name, serve_world};
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::tungstenite::protocol::frame::coding::CloseCode;

type Socket =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

fn runtime() -> tokio::runtime::Runtime {
    tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .unwrap()
}

async fn open(port: u16) -> Socket {
    let url = format!("ws://127.0.0.1:{port}/ws");
    tokio_tungstenite::connect_async(url)
        .await
        .expect("the socket opens")
        .0
}

/// The next JSON frame of type `kind`, skipping the rest; at most 10 s.
async fn next_of(socket: &mut Socket, kind: &str) -> Value {
    let wait = async {
        loop {
            match socket.next().await {
                Some(Ok(Message::Text(text))) => {
                    let value: Value = serde_json::from_str(&text).expect("frames are JSON");
                    if value["type"] == kind {
                        return value;
                    }
                }
                Some(Ok(_)) => {}
                other => panic!("the socket ended waiting for {kind}: {other:?}"),
            }
        }
    };
    tokio::time::timeout(Duration::from_secs(10), wait)
        .await
        .unwrap_or_else(|_| panic!("no {kind} frame in 10 s"))
}

#[test]
fn bad_frames_and_commands_get_a_clear_refusal_and_the_socket_stays() {
    let running = serve_world("simple.world", None);
    let front = Front::start(&running, Commanders::Nobody);
    let port = front.web.port();
    let robot = robot_name(&running, 6665);
    runtime().block_on(async {
        let mut page = open(port).await;
        let hello = next_of(&mut page, "hello").await;
        assert_eq!(hello["controller"], false);
        let cases = [
            (Message::text("{ not json"), "not a command"),
            (Message::text(r#"{"type":"fly","robot":"x"}"#), "unknown variant `fly`"),
            (Message::binary(vec![0u8, 1, 2, 3]), "binary frames"),
            (
                Message::text(r#"{"type":"velocity","robot":"nowhere:1","device":"position2d:0","command":{"vel":{"px":1,"py":0,"pa":0},"state":1}}"#),
                "no robot \"nowhere:1\"",
            ),
            (
                Message::text(format!(r#"{{"type":"velocity","robot":"{robot}","device":"laser:0","command":{{"vel":{{"px":1,"py":0,"pa":0}},"state":1}}}}"#)),
                "laser:0 is not a position2d device",
            ),
            (
                Message::text(format!(r#"{{"type":"velocity","robot":"{robot}","device":"position2d:0","command":{{"vel":{{"px":1,"py":0,"pa":0}},"state":1}}}}"#)),
                "nobody may command: this page only observes",
            ),
            (
                Message::text(format!(r#"{{"type":"goal","robot":"{robot}","device":"position2d:7","goal":{{"px":1,"py":0,"pa":0}}}}"#)),
                "has no position2d:7",
            ),
        ];
        for (frame, expected) in cases {
            page.send(frame.clone()).await.unwrap();
            let refused = next_of(&mut page, "refused").await;
            let why = refused["why"].as_str().unwrap();
            assert!(why.contains(expected), "{frame:?}: {why:?} should say {expected:?}");
        }
        // Still served after all that.
        next_of(&mut page, "status").await;
        // An oversized frame closes this socket with "message too big" (1009), not others.
        let mut bystander = open(port).await;
        next_of(&mut bystander, "status").await;
        page.send(Message::text("x".repeat(100_000))).await.unwrap();
        let closed = tokio::time::timeout(Duration::from_secs(10), async {
            loop {
                match page.next().await {
                    Some(Ok(Message::Close(frame))) => return frame.map(|f| f.code),
                    Some(Ok(_)) => {}
                    _ => return None,
                }
            }
        })
        .await
        .expect("the oversized frame's socket closes");
        assert_eq!(closed, Some(CloseCode::Size));
        next_of(&mut bystander, "status").await;
    });
    assert_eq!(
        running.sim.lock().unwrap().robots[0].velocity,
        (0.0, 0.0, 0.0)
    );
}

#[test]
fn a_page_that_never_reads_is_closed_and_holds_nobody_up() {
    let running = serve_world("navigation.world", None);
    let front = Front::start(&running, Commanders::Nobody);
    let port = front.web.port();
    runtime().block_on(async {
        // A client whose kernel takes little before it stops reading altogether.
        let socket = tokio::net::TcpSocket::new_v4().unwrap();
        socket.set_recv_buffer_size(16 * 1024).unwrap();
        let tcp = socket.connect(([127, 0, 0, 1], port).into()).await.unwrap();
        let url = format!("ws://127.0.0.1:{port}/ws");
        let (mut stalled, _) = tokio_tungstenite::client_async(url, tcp).await.unwrap();
        let mut reader = open(port).await;
        let started = Instant::now();
        let mut rows = 0;
        // The reader keeps getting its rows while the stalled one fills its buffers and is
        // dropped by the server (every front's STALLED_AFTER after they fill): a stalled
        // page that read again sooner would be served again.
        let stall = player_front::STALLED_AFTER + Duration::from_secs(7);
        while started.elapsed() < stall {
            next_of(&mut reader, "status").await;
            rows += 1;
        }
        let least = stall.as_secs() - 2;
        assert!(rows >= least, "the reader got {rows} rows in {stall:?}");
        // Now read what the stalled one was sent: it ends in a close (or a reset).
        let ended = tokio::time::timeout(Duration::from_secs(10), async {
            let mut frames = 0u64;
            loop {
                match stalled.next().await {
                    Some(Ok(Message::Close(frame))) => {
                        return (frames, frame.map(|f| f.reason.to_string()));
                    }
                    Some(Ok(_)) => frames += 1,
                    _ => return (frames, None),
                }
            }
        })
        .await
        .expect("the stalled page's socket was closed by the server");
        eprintln!(
            "the stalled page got {} frames before its close ({:?})",
            ended.0, ended.1
        );
        if let Some(reason) = ended.1 {
            assert!(reason.contains("not reading"), "{reason}");
        }
    });
}

#[test]
fn five_hundred_pages_opening_at_once_are_all_served() {
    const PAGES: usize = 500;
    let running = serve_world("simple.world", None);
    let front = Front::start(&running, Commanders::Nobody);
    let port = front.web.port();
    let rss_before = resident_kib();
    let started = Instant::now();
    let served = runtime().block_on(async {
        let pages: Vec<_> = (0..PAGES)
            .map(|_| {
                tokio::spawn(async move {
                    let mut page = open(port).await;
                    next_of(&mut page, "hello").await;
                    next_of(&mut page, "message").await;
                    next_of(&mut page, "status").await;
                    page
                })
            })
            .collect();
        let mut open_pages = Vec::new();
        for page in pages {
            open_pages.push(page.await.expect("every page is served"));
        }
        let rss_open = resident_kib();
        eprintln!(
            "{PAGES} pages served in {:.1} s; resident {} → {} KiB (test process: clients and server)",
            started.elapsed().as_secs_f64(),
            rss_before,
            rss_open
        );
        open_pages.len()
    });
    assert_eq!(served, PAGES);
}

fn resident_kib() -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmRSS:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse().ok())
        })
        .unwrap_or(0)
}

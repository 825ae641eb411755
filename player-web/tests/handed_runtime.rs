//! The page on a runtime it was handed (as the relay hands one to all its fronts): it serves
//! the page and its socket there, and once dropped its port is free, its pages and HTTP
//! connections are closed and its tasks gone — while the handed runtime runs on.

use std::io::{Read, Write};
use std::net::{IpAddr, Ipv4Addr, TcpListener, TcpStream};
use std::time::{Duration, Instant};

use futures_util::StreamExt;
use player_proto::server::Commanders;
use player_web::WebFront;
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::tungstenite::protocol::frame::coding::CloseCode;

const LOCALHOST: IpAddr = IpAddr::V4(Ipv4Addr::LOCALHOST);
const PATIENCE: Duration = Duration::from_secs(10);

/// The first line of the answer to `GET /` on a kept-alive connection, and the connection.
fn get_page(port: u16) -> (String, TcpStream) {
    let mut http = TcpStream::connect((LOCALHOST, port)).expect("the page's port answers");
    http.set_read_timeout(Some(PATIENCE)).unwrap();
    http.write_all(b"GET / HTTP/1.1\r\nHost: localhost\r\n\r\n")
        .unwrap();
    let mut answer = vec![0u8; 4096];
    let n = http.read(&mut answer).expect("the page is answered");
    let answer = String::from_utf8_lossy(&answer[..n]).into_owned();
    (answer.lines().next().unwrap_or_default().to_string(), http)
}

/// Whether a listener can be bound on `port` within the test's patience.
fn port_freed(port: u16) -> bool {
    let deadline = Instant::now() + PATIENCE;
    while Instant::now() < deadline {
        if TcpListener::bind((LOCALHOST, port)).is_ok() {
            return true;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    false
}

#[test]
fn a_page_on_a_handed_runtime_serves_and_is_gone_when_dropped_and_the_runtime_is_not() {
    let handed = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .unwrap();
    let web = WebFront::start_on(handed.handle().clone(), LOCALHOST, 0, Commanders::Nobody)
        .expect("the page is served");
    let port = web.port();
    // Its listener and its status rows.
    assert_eq!(web.tasks(), 2);
    let (status, mut http) = get_page(port);
    assert_eq!(status, "HTTP/1.1 200 OK");
    let url = format!("ws://127.0.0.1:{port}/ws");
    let mut page = handed
        .block_on(tokio_tungstenite::connect_async(url))
        .expect("the page's socket opens")
        .0;
    let hello = handed.block_on(async {
        tokio::time::timeout(PATIENCE, page.next())
            .await
            .expect("the page is greeted")
    });
    assert!(
        matches!(&hello, Some(Ok(Message::Text(t))) if t.contains("\"hello\"")),
        "{hello:?}"
    );

    drop(web);

    // The open page is told the server goes (1001), and the socket ends.
    let closed = handed.block_on(async {
        tokio::time::timeout(PATIENCE, async {
            loop {
                match page.next().await {
                    Some(Ok(Message::Close(frame))) => return frame.map(|f| f.code),
                    Some(Ok(_)) => continue,
                    other => panic!("the socket ended without a close: {other:?}"),
                }
            }
        })
        .await
        .expect("the page is closed")
    });
    assert_eq!(closed, Some(CloseCode::Away));
    // The kept-alive HTTP connection is let go too.
    let mut rest = Vec::new();
    let ended = http.read_to_end(&mut rest);
    assert!(ended.is_ok(), "the HTTP connection ends: {ended:?}");
    assert!(port_freed(port), "port {port} is still held");
    // The handed runtime runs on.
    let ran = handed.block_on(handed.spawn(async { 7 })).unwrap();
    assert_eq!(ran, 7);
}

//! `pv3d --serve-web PORT`: the viewer's own robots on the relay's web page, over a real
//! WebSocket — every robot of the world with its scans, read-only (a command from the page is
//! refused and nothing moves), while `--record` beside it still records everything.

mod support;

use std::io::{BufRead, BufReader};
use std::process::{Child, Stdio};
use std::time::Duration;

use futures_util::{SinkExt, StreamExt};
use player_proto::recording::{Event, RecordingReader};
use serde_json::Value;
use support::pv3d;
use tokio_tungstenite::tungstenite::Message;

/// Kills the viewer if the test fails before it quits by itself.
struct Running(Child);

impl Drop for Running {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// The port pv3d says it serves the page on, from its stderr.
fn served_port(child: &mut Child) -> u16 {
    let mut stderr = BufReader::new(child.stderr.take().expect("stderr"));
    let mut line = String::new();
    loop {
        line.clear();
        assert!(
            stderr.read_line(&mut line).unwrap() > 0,
            "pv3d ended without serving the page"
        );
        if let Some(rest) = line.split("web page of these robots on port ").nth(1) {
            let port = rest.split(':').next().unwrap().trim();
            // The rest of stderr is drained so that the viewer never blocks on it.
            std::thread::spawn(move || std::io::copy(&mut stderr, &mut std::io::sink()));
            return port.parse().expect("a port number");
        }
    }
}

#[test]
fn the_viewers_robots_are_on_its_web_page_read_only_and_still_recorded() {
    let dir = tempfile::tempdir().unwrap();
    let recording = dir.path().join("run.prec");
    let child = pv3d()
        .args(["--world", "stage-worlds/multirobot.world", "--headless"])
        .args(["--serve-web", "0", "--quit-after", "12"])
        .arg("--record")
        .arg(&recording)
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .stderr(Stdio::piped())
        .spawn()
        .expect("pv3d runs");
    let mut viewer = Running(child);
    let port = served_port(&mut viewer.0);

    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .unwrap();
    let (hello, scanned, refused) = runtime.block_on(async {
        let url = format!("ws://127.0.0.1:{port}/ws");
        let (mut socket, _) = tokio_tungstenite::connect_async(url)
            .await
            .expect("the page's socket opens");
        let mut hello = Value::Null;
        let mut scanned = std::collections::BTreeSet::new();
        let mut refused = None;
        let watch = async {
            while let Some(Ok(frame)) = socket.next().await {
                let Message::Text(text) = frame else { continue };
                let value: Value = serde_json::from_str(&text).expect("frames are JSON");
                match value["type"].as_str() {
                    Some("hello") => hello = value,
                    Some("message")
                        if value["kind"] == "data"
                            && value["device"]
                                .as_str()
                                .is_some_and(|d| d.starts_with("laser:")) =>
                    {
                        let robot = value["robot"].as_str().unwrap().to_string();
                        // The first robot's scan is seen: an observer asks it to move.
                        if scanned.is_empty() {
                            let command = format!(
                                r#"{{"type":"velocity","robot":"{robot}","device":"position2d:0","command":{{"vel":{{"px":1,"py":0,"pa":0}},"state":1}}}}"#
                            );
                            socket.send(Message::text(command)).await.unwrap();
                        }
                        scanned.insert(robot);
                    }
                    Some("refused") => refused = Some(value),
                    _ => {}
                }
                if scanned.len() >= 5 && refused.is_some() {
                    break;
                }
            }
        };
        let _ = tokio::time::timeout(Duration::from_secs(30), watch).await;
        (hello, scanned, refused)
    });
    assert_eq!(hello["controller"], false, "the page is read-only: {hello}");
    assert!(
        scanned.len() >= 5,
        "multirobot.world's five robots' lasers on the page, saw {scanned:?}"
    );
    let refused = refused.expect("the observer's command is refused");
    assert!(
        refused["why"].as_str().unwrap().contains("read-only"),
        "{refused}"
    );

    // The recording beside the page got everything too.
    assert!(viewer.0.wait().unwrap().success(), "pv3d quits by itself");
    let file = std::fs::File::open(&recording).unwrap();
    let mut reader = RecordingReader::new(std::io::BufReader::new(file)).unwrap();
    let mut messages = 0;
    while let Some(record) = reader.next_record().unwrap() {
        if matches!(record.event, Event::Message { .. }) {
            messages += 1;
        }
    }
    assert!(messages > 100, "the recording kept recording: {messages}");
}

//! Web pages for a [`Crowd`]: each opens the relay's page socket (`player-relay --web`), as a
//! browser tab does, and takes the latency of every data message from the server's timestamp
//! in its envelope to its arrival here. Only the envelope's head is read (the time comes
//! before the body): the benchmark measures the relay, not a JSON parser.

use std::time::Duration;

use futures_util::StreamExt;
use tokio_tungstenite::tungstenite::Message;

use crate::BenchError;
use crate::clock::{SharedWindow, unix_seconds};
use crate::crowd::{Crowd, Member, Seen};

/// Opens `count` pages on the web port and waits (at most `timeout`) until each has its
/// hello.
pub fn connect_pages(
    port: u16,
    count: usize,
    window: SharedWindow,
    timeout: Duration,
) -> Result<Crowd, BenchError> {
    Crowd::start("web pages", count, window, timeout, move |member| {
        page(port, member)
    })
}

async fn page(port: u16, member: Member) -> Seen {
    let Member {
        window,
        mut stop,
        ready,
        ..
    } = member;
    let url = format!("ws://127.0.0.1:{port}/ws");
    let (mut socket, _) = tokio_tungstenite::connect_async(url)
        .await
        .map_err(|e| format!("page socket on {port}: {e}"))?;
    let mut latencies = Vec::new();
    let mut hello = false;
    loop {
        tokio::select! {
            _ = stop.changed() => return Ok(latencies),
            frame = socket.next() => match frame {
                Some(Ok(Message::Text(text))) => {
                    if !hello {
                        hello = true;
                        let _ = ready.send(()).await;
                    }
                    if let Some(sent) = data_time(&text)
                        && window.contains(sent)
                    {
                        latencies.push(unix_seconds() - sent);
                    }
                }
                Some(Ok(_)) => {}
                Some(Err(e)) => return Err(format!("page socket: {e}")),
                None => return Err("the relay closed a page's socket".into()),
            },
        }
    }
}

/// The server's timestamp of a data message's envelope (`{"type":"message",…,"kind":"data",
/// …,"time":…,"body":…}`), from the text before its body.
pub fn data_time(text: &str) -> Option<f64> {
    let head = &text[..text.find(",\"body\":")?];
    if !head.starts_with("{\"type\":\"message\"") || !head.contains("\"kind\":\"data\"") {
        return None;
    }
    let time = &head[head.find("\"time\":")? + 7..];
    let end = time.find([',', '}']).unwrap_or(time.len());
    time[..end].parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_data_envelopes_time_is_read_from_its_head() {
        let data = r#"{"type":"message","robot":"127.0.0.1:1","kind":"data","device":"laser:0","subtype":1,"time":1764000000.25,"body":{"Laser":{"Scan":{"time":5}}}}"#;
        assert_eq!(data_time(data), Some(1764000000.25));
        let reply = data.replace("\"data\"", "\"reply\"");
        assert_eq!(data_time(&reply), None);
        assert_eq!(data_time(r#"{"type":"status","rows":[]}"#), None);
    }
}

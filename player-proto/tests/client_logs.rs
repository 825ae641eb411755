//! What the client logs about its connection, seen through a subscriber that records every
//! event (in its own test binary: the subscriber is global, as the robot thread is its own
//! thread).

use std::io::Write;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use player_proto::client::{Backoff, Client, ClientOptions, ConnectionState};
use player_proto::server::{Server, ServerConfig};

/// Collects formatted log lines.
#[derive(Clone, Default)]
struct Lines(Arc<Mutex<Vec<u8>>>);

impl Write for Lines {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        self.0.lock().unwrap().extend_from_slice(bytes);
        Ok(bytes.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl Lines {
    fn text(&self) -> String {
        String::from_utf8_lossy(&self.0.lock().unwrap()).into_owned()
    }
}

fn server(port: u16) -> Server {
    let mut config = ServerConfig::default();
    config.robot(port);
    Server::start(config).unwrap()
}

#[test]
fn a_lost_connection_that_comes_back_is_logged_as_reconnected() {
    let lines = Lines::default();
    let writer = lines.clone();
    tracing::subscriber::set_global_default(
        tracing_subscriber::fmt()
            .with_ansi(false)
            .with_writer(move || writer.clone())
            .finish(),
    )
    .unwrap();
    let s = server(0);
    let port = s.port(0);
    let options = ClientOptions {
        backoff: Backoff {
            initial: Duration::from_millis(50),
            max: Duration::from_millis(200),
            max_attempts: None,
        },
        ..ClientOptions::default()
    };
    let client = Client::connect("127.0.0.1", port, options).unwrap();
    assert!(!lines.text().contains("reconnected"), "{}", lines.text());

    drop(s);
    let gone = client.wait_for_state(Duration::from_secs(5), |s| *s != ConnectionState::Connected);
    assert!(gone.is_some(), "the loss is noticed");
    let _s = server(port);
    let back = client.wait_for_state(Duration::from_secs(5), |s| *s == ConnectionState::Connected);
    assert!(back.is_some(), "the server is found again");
    let log = lines.text();
    assert!(log.contains("connection lost"), "{log}");
    assert!(
        log.lines()
            .any(|l| l.contains("INFO") && l.contains("reconnected")),
        "{log}"
    );
}

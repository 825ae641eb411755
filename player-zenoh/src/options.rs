//! How to join Zenoh, in the terms a Zenoh user expects: a mode (peer, client or router),
//! endpoints to connect to and to listen on (`tcp/10.0.0.1:7447`), or Zenoh's own JSON5
//! configuration file, which the other options then amend.

use std::path::PathBuf;
use std::str::FromStr;
use std::time::Duration;

use crate::error::ZenohError;

/// Zenoh's three roles.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mode {
    /// Talks directly to other peers (and routers); the default.
    #[default]
    Peer,
    /// Talks through one router only.
    Client,
    /// Routes for others.
    Router,
}

/// A mode Zenoh does not have.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("expected peer, client or router, got {0:?}")]
pub struct UnknownMode(pub String);

impl FromStr for Mode {
    type Err = UnknownMode;
    fn from_str(text: &str) -> Result<Mode, UnknownMode> {
        match text {
            "peer" => Ok(Mode::Peer),
            "client" => Ok(Mode::Client),
            "router" => Ok(Mode::Router),
            _ => Err(UnknownMode(text.to_string())),
        }
    }
}

impl Mode {
    fn name(self) -> &'static str {
        match self {
            Mode::Peer => "peer",
            Mode::Client => "client",
            Mode::Router => "router",
        }
    }
}

/// Where and how to join Zenoh.
#[derive(Debug, Clone, Default)]
pub struct ZenohOptions {
    /// Zenoh's JSON5 configuration file, read first.
    pub config_file: Option<PathBuf>,
    /// `None` keeps the file's mode (or Zenoh's default, peer).
    pub mode: Option<Mode>,
    /// Endpoints to connect to, e.g. `tcp/192.168.1.10:7447`.
    pub connect: Vec<String>,
    /// Endpoints to listen on.
    pub listen: Vec<String>,
    /// Turns multicast and gossip scouting off: only the endpoints given are used. Tests
    /// need it (peers on one machine would otherwise find each other by themselves).
    pub no_scouting: bool,
    /// How long opening the session keeps trying `connect` endpoints that do not answer
    /// (`Duration::MAX`: until one does); `None` keeps Zenoh's default, under which a client
    /// gives up at once. A relay started before its router should wait for it, as a daemon
    /// waits for its network; a viewer waits a while, then says what it could not reach.
    pub connect_patience: Option<Duration>,
}

impl ZenohOptions {
    /// The Zenoh configuration these options describe.
    pub fn config(&self) -> Result<zenoh::Config, ZenohError> {
        let mut config = match &self.config_file {
            Some(path) => zenoh::Config::from_file(path)?,
            None => zenoh::Config::default(),
        };
        if let Some(mode) = self.mode {
            config.insert_json5("mode", &json_string(mode.name()))?;
        }
        if !self.connect.is_empty() {
            config.insert_json5("connect/endpoints", &json_list(&self.connect))?;
        }
        if !self.listen.is_empty() {
            config.insert_json5("listen/endpoints", &json_list(&self.listen))?;
        }
        if let Some(patience) = self.connect_patience {
            let ms = match patience {
                Duration::MAX => -1,
                d => i64::try_from(d.as_millis()).unwrap_or(i64::MAX),
            };
            config.insert_json5("connect/timeout_ms", &ms.to_string())?;
        }
        if self.no_scouting {
            config.insert_json5("scouting/multicast/enabled", "false")?;
            config.insert_json5("scouting/gossip/enabled", "false")?;
        }
        Ok(config)
    }

    /// Opens a session.
    pub fn open(&self) -> Result<zenoh::Session, ZenohError> {
        use zenoh::Wait;
        Ok(zenoh::open(self.config()?).wait()?)
    }
}

fn json_string(text: &str) -> String {
    format!("\"{}\"", text.replace('\\', "\\\\").replace('"', "\\\""))
}

fn json_list(items: &[String]) -> String {
    let items: Vec<String> = items.iter().map(|i| json_string(i)).collect();
    format!("[{}]", items.join(","))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_options_make_a_zenoh_config() {
        let options = ZenohOptions {
            mode: Some(Mode::Client),
            connect: vec!["tcp/127.0.0.1:7447".into()],
            listen: vec!["tcp/127.0.0.1:0".into()],
            no_scouting: true,
            ..ZenohOptions::default()
        };
        options.config().expect("Zenoh accepts it");
        assert_eq!("router".parse(), Ok(Mode::Router));
        assert_eq!("hub".parse::<Mode>(), Err(UnknownMode("hub".into())));
    }

    fn free_port() -> u16 {
        std::net::TcpListener::bind("127.0.0.1:0")
            .and_then(|l| l.local_addr())
            .expect("a free port")
            .port()
    }

    fn client_of(port: u16, patience: Duration) -> ZenohOptions {
        ZenohOptions {
            mode: Some(Mode::Client),
            connect: vec![format!("tcp/127.0.0.1:{port}")],
            no_scouting: true,
            connect_patience: Some(patience),
            ..ZenohOptions::default()
        }
    }

    #[test]
    fn a_client_started_before_its_router_waits_for_it() {
        let port = free_port();
        let client = std::thread::spawn(move || client_of(port, Duration::MAX).open());
        std::thread::sleep(Duration::from_millis(1500));
        assert!(!client.is_finished(), "the client is still waiting");
        let _router = ZenohOptions {
            mode: Some(Mode::Router),
            listen: vec![format!("tcp/127.0.0.1:{port}")],
            no_scouting: true,
            ..ZenohOptions::default()
        }
        .open()
        .expect("the router opens");
        let session = client.join().expect("no panic");
        assert!(
            session.is_ok(),
            "joined once the router listened: {session:?}"
        );
    }

    #[test]
    fn a_client_whose_patience_runs_out_says_where_it_could_not_connect() {
        let port = free_port();
        let started = std::time::Instant::now();
        let error = client_of(port, Duration::from_millis(800))
            .open()
            .expect_err("nobody listens there");
        assert!(
            started.elapsed() < Duration::from_secs(10),
            "{:?}",
            started.elapsed()
        );
        assert!(error.to_string().contains(&port.to_string()), "{error}");
    }
}

//! How to join Zenoh, in the terms a Zenoh user expects: a mode (peer, client or router),
//! endpoints to connect to and to listen on (`tcp/10.0.0.1:7447`), or Zenoh's own JSON5
//! configuration file, which the other options then amend.

use std::path::PathBuf;
use std::str::FromStr;

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

impl FromStr for Mode {
    type Err = String;
    fn from_str(text: &str) -> Result<Mode, String> {
        match text {
            "peer" => Ok(Mode::Peer),
            "client" => Ok(Mode::Client),
            "router" => Ok(Mode::Router),
            _ => Err(format!("expected peer, client or router, got {text:?}")),
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
        assert!("hub".parse::<Mode>().is_err());
    }
}

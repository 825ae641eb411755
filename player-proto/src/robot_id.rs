//! Who a robot is: the Player server that serves it (host and port) and, where the world or
//! the person gives one, its name. Every place that shows or files a robot — the web page's
//! rows, Foxglove topics, Zenoh keys, logs — says it as [`RobotId`]'s `Display` does: the name
//! where there is one, else `host:port`.
//!
//! A name is written on a command line as `HOST:PORT=NAME` and comes from a simulated world's
//! models. It ends up in topics and keys, so it is kept to what every one of them takes as it
//! is: letters, digits, `_`, `-` and `.`, at most [`NAME_MAX`] characters, not all digits (a
//! number after `=` is a port).

use std::fmt;
use std::str::FromStr;

/// The longest name, in characters.
pub const NAME_MAX: usize = 64;

/// A robot: its server, and its name when it has one.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct RobotId {
    host: String,
    port: u16,
    name: Option<String>,
}

/// Why a robot cannot be named or read from text.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum RobotIdError {
    #[error("expected HOST:PORT[=NAME], got {0:?}")]
    NoPort(String),
    #[error("no host in {0:?}")]
    NoHost(String),
    #[error("bad port {port:?} in {text:?}")]
    BadPort { port: String, text: String },
    #[error("bad robot name {name:?}: {why}")]
    BadName { name: String, why: &'static str },
}

impl RobotId {
    /// The robot served at `host:port`, with no name.
    pub fn new(host: impl Into<String>, port: u16) -> RobotId {
        RobotId {
            host: host.into(),
            port,
            name: None,
        }
    }

    /// The same robot, named `name` (see the module's rule for names).
    pub fn named(self, name: impl Into<String>) -> Result<RobotId, RobotIdError> {
        let name = name.into();
        check_name(&name)?;
        Ok(RobotId {
            name: Some(name),
            ..self
        })
    }

    pub fn host(&self) -> &str {
        &self.host
    }

    pub fn port(&self) -> u16 {
        self.port
    }

    pub fn name(&self) -> Option<&str> {
        self.name.as_deref()
    }

    /// `host:port`, whatever the name.
    pub fn server(&self) -> String {
        format!("{}:{}", self.host, self.port)
    }
}

/// The name, else `host:port`.
impl fmt::Display for RobotId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.name {
            Some(name) => f.write_str(name),
            None => write!(f, "{}:{}", self.host, self.port),
        }
    }
}

/// `HOST:PORT` or `HOST:PORT=NAME` (an IPv6 host in brackets or not: the port follows the
/// last `:`).
impl FromStr for RobotId {
    type Err = RobotIdError;

    fn from_str(text: &str) -> Result<RobotId, RobotIdError> {
        let (server, name) = match text.split_once('=') {
            Some((server, name)) => (server, Some(name)),
            None => (text, None),
        };
        let (host, port) = server
            .rsplit_once(':')
            .ok_or_else(|| RobotIdError::NoPort(text.to_string()))?;
        if host.is_empty() {
            return Err(RobotIdError::NoHost(text.to_string()));
        }
        let port = port.parse::<u16>().map_err(|_| RobotIdError::BadPort {
            port: port.to_string(),
            text: text.to_string(),
        })?;
        let id = RobotId::new(host, port);
        match name {
            Some(name) => id.named(name),
            None => Ok(id),
        }
    }
}

/// Whether `name` may name a robot (see the module's rule).
pub fn check_name(name: &str) -> Result<(), RobotIdError> {
    let bad = |why| {
        Err(RobotIdError::BadName {
            name: name.to_string(),
            why,
        })
    };
    if name.is_empty() {
        return bad("empty");
    }
    if name.chars().count() > NAME_MAX {
        return bad("longer than 64 characters");
    }
    if !name
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.'))
    {
        return bad("only letters, digits, '_', '-' and '.'");
    }
    if name.chars().all(|c| c.is_ascii_digit()) {
        return bad("a number reads as a port");
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_robot_is_said_by_its_name_else_by_its_server() {
        let plain = RobotId::new("10.0.0.2", 6665);
        assert_eq!(plain.to_string(), "10.0.0.2:6665");
        let named = plain.clone().named("r0").unwrap();
        assert_eq!(named.to_string(), "r0");
        assert_eq!(named.server(), "10.0.0.2:6665");
        assert_ne!(plain, named);
    }

    #[test]
    fn the_command_line_form_reads_back() {
        let id: RobotId = "robot1.local:6666=scout-2".parse().unwrap();
        assert_eq!(
            (id.host(), id.port(), id.name()),
            ("robot1.local", 6666, Some("scout-2"))
        );
        let id: RobotId = "::1:6665".parse().unwrap();
        assert_eq!((id.host(), id.port(), id.name()), ("::1", 6665, None));
    }

    #[test]
    fn what_is_not_a_robot_is_refused_with_its_reason() {
        let refused = |text: &str| text.parse::<RobotId>().unwrap_err();
        assert!(matches!(refused("localhost"), RobotIdError::NoPort(_)));
        assert!(matches!(refused(":6665"), RobotIdError::NoHost(_)));
        assert!(matches!(refused("h:66x"), RobotIdError::BadPort { .. }));
        for name in ["", "a/b", "two words", "r*", "7000", &"x".repeat(65)] {
            assert!(
                matches!(
                    refused(&format!("h:1={name}")),
                    RobotIdError::BadName { .. }
                ),
                "{name:?} is no name"
            );
        }
        assert!(check_name(&"x".repeat(64)).is_ok());
    }
}

//! The key space. Every robot is `player/<site>/<robot>`: its name where it has one (given on
//! the relay's command line or by the world it simulates: see `player_proto::RobotId`), else
//! `<host>_<port>`, named after the Player server the publishing relay reaches it at. So two
//! sites never clash and a robot keeps its key across restarts (a bridge finds it again under
//! the same key and serves it on the same port). Under it:
//!
//! | key | what |
//! |---|---|
//! | `…/alive` | liveliness token while the relay is connected to the robot |
//! | `…/devices` | queryable: the device list and driver names, as Player replies |
//! | `…/<interface>/<index>/data` | every DATA message, raw Player bytes |
//! | `…/<interface>/<index>/replies` | queryable: the cached replies describing the device |
//! | `…/<interface>/<index>/cmd` | commands (put) and requests (get) to the robot |
//!
//! `<interface>` is Player's interface name (`laser`, `position2d`), so a person can
//! subscribe to `player/*/*/laser/*/data` without a table of codes.

use std::fmt;

use player_proto::RobotId;
use player_proto::wire::Interface;

/// The first chunk of every key.
pub const ROOT: &str = "player";

/// One robot's place in the key space.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct RobotKey {
    pub site: String,
    /// The robot's name, else `<host>_<port>`, with characters Zenoh keys may not hold
    /// replaced.
    pub robot: String,
}

/// A chunk of a key: no `/`, no wildcards or reserved characters, never empty.
pub fn chunk(text: &str) -> String {
    let cleaned: String = text
        .chars()
        .map(|c| match c {
            '/' | '*' | '$' | '?' | '#' | '@' | ' ' => '-',
            c => c,
        })
        .collect();
    if cleaned.is_empty() {
        "-".into()
    } else {
        cleaned
    }
}

impl RobotKey {
    /// The key of the unnamed robot served at `host:port`.
    pub fn new(site: &str, host: &str, port: u16) -> RobotKey {
        RobotKey {
            site: chunk(site),
            robot: chunk(&format!("{host}_{port}")),
        }
    }

    /// The key of `robot`: its name where it has one.
    pub fn of_robot(site: &str, robot: &RobotId) -> RobotKey {
        match robot.name() {
            Some(name) => RobotKey {
                site: chunk(site),
                robot: chunk(name),
            },
            None => RobotKey::new(site, robot.host(), robot.port()),
        }
    }

    /// The robot named by a key under `player/<site>/<robot>/…`.
    pub fn of_key(key: &str) -> Option<RobotKey> {
        let mut chunks = key.split('/');
        (chunks.next()? == ROOT).then_some(())?;
        let site = chunks.next()?.to_string();
        let robot = chunks.next()?.to_string();
        Some(RobotKey { site, robot })
    }

    pub fn alive(&self) -> String {
        format!("{self}/alive")
    }

    pub fn devices(&self) -> String {
        format!("{self}/devices")
    }

    pub fn device(&self, interf: Interface, index: u16, leaf: Leaf) -> String {
        format!("{self}/{}/{index}/{leaf}", interface_chunk(interf))
    }
}

impl fmt::Display for RobotKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{ROOT}/{}/{}", self.site, self.robot)
    }
}

/// What a device key leads to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Leaf {
    Data,
    Replies,
    Cmd,
}

impl fmt::Display for Leaf {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Leaf::Data => "data",
            Leaf::Replies => "replies",
            Leaf::Cmd => "cmd",
        })
    }
}

/// Every robot's `alive` token on a site (`*` for every site).
pub fn alive_of_site(site: &str) -> String {
    format!("{ROOT}/{}/*/alive", site_chunk(site))
}

/// Every device key with this leaf on a site: what a front's queryables and subscribers
/// answer for all its robots at once.
pub fn every_device(site: &str, leaf: Leaf) -> String {
    format!("{ROOT}/{}/*/*/*/{leaf}", site_chunk(site))
}

/// Every robot's `devices` key on a site.
pub fn every_devices(site: &str) -> String {
    format!("{ROOT}/{}/*/devices", site_chunk(site))
}

fn site_chunk(site: &str) -> String {
    if site == "*" {
        site.into()
    } else {
        chunk(site)
    }
}

/// Player's name for an interface, or its code for one without a name.
pub fn interface_chunk(interf: Interface) -> String {
    chunk(&interf.to_string())
}

/// The device (interface, index) a device key names.
pub fn device_of_key(key: &str) -> Option<(Interface, u16, Leaf)> {
    let chunks: Vec<&str> = key.split('/').collect();
    let [_, _, _, interf, index, leaf] = chunks.as_slice() else {
        return None;
    };
    let leaf = match *leaf {
        "data" => Leaf::Data,
        "replies" => Leaf::Replies,
        "cmd" => Leaf::Cmd,
        _ => return None,
    };
    Some((parse_interface(interf)?, index.parse().ok()?, leaf))
}

fn parse_interface(text: &str) -> Option<Interface> {
    if let Ok(code) = text.parse::<u16>() {
        return Some(Interface(code));
    }
    Interface::KNOWN
        .iter()
        .find(|(_, name)| *name == text)
        .map(|(interf, _)| *interf)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_device_key_names_its_robot_and_device() {
        let robot = RobotKey::new("lab A", "10.0.0.2", 6665);
        let key = robot.device(Interface::LASER, 0, Leaf::Data);
        assert_eq!(key, "player/lab-A/10.0.0.2_6665/laser/0/data");
        assert_eq!(RobotKey::of_key(&key), Some(robot));
        assert_eq!(device_of_key(&key), Some((Interface::LASER, 0, Leaf::Data)));
    }

    #[test]
    fn a_named_robot_is_keyed_by_its_name() {
        let robot = RobotId::new("10.0.0.2", 6665);
        assert_eq!(
            RobotKey::of_robot("A", &robot),
            RobotKey::new("A", "10.0.0.2", 6665)
        );
        let named = RobotKey::of_robot("A", &robot.named("r0").unwrap());
        assert_eq!(named.alive(), "player/A/r0/alive");
    }

    #[test]
    fn reserved_characters_never_reach_a_key() {
        assert_eq!(chunk("a/b*c$d"), "a-b-c-d");
        assert_eq!(chunk(""), "-");
    }
}

//! Robots found in Zenoh, opened as any other robots: `pv3d --zenoh tcp/router:7447` joins
//! Zenoh, serves every robot it finds under `player/<site>/` as a Player server on a free
//! loopback port ([`player_zenoh::FromZenoh`], the bridge `player-relay --from-zenoh` runs),
//! and points the composition's Player clients there. The viewer itself stays a Player
//! client over real TCP: nothing above the bridge knows the robots are far away, and a robot
//! whose link breaks and heals comes back on the same port, where the clients reconnect.

use std::time::{Duration, Instant};

use player_zenoh::{FromZenoh, FromZenohConfig, Mode, RobotKey, ZenohError, ZenohOptions};

use crate::composition::{ClientDecl, Composition, SourcePos};

/// How long discovery may stay quiet before the robots found are taken as all there is.
const QUIET: Duration = Duration::from_millis(1500);

/// Where to find the robots, and who this viewer is to them.
#[derive(Debug, Clone, Default)]
pub struct ZenohSource {
    /// Endpoints to connect to (`tcp/10.0.0.1:7447`), a router's or a robot relay's.
    pub connect: Vec<String>,
    /// Zenoh's own JSON5 configuration file, amended by the endpoints.
    pub config_file: Option<std::path::PathBuf>,
    /// The site whose robots are opened; `*` for every site.
    pub site: String,
    /// Sent with commands: the robots' relays execute those of their controller only.
    /// `None`: this session's Zenoh id (so nobody's controller unless configured so).
    pub identity: Option<String>,
}

/// Why robots could not be had from Zenoh.
#[derive(Debug, thiserror::Error)]
pub enum ZenohRobotsError {
    #[error("cannot join Zenoh at {endpoints}")]
    Join {
        endpoints: String,
        source: ZenohError,
    },
    #[error(
        "no robot found in Zenoh under player/{site}/ within {seconds:.1} s (is a relay \
         publishing them with `player-relay --zenoh --site {site}`, reachable at {endpoints}?)"
    )]
    NoRobots {
        site: String,
        seconds: f64,
        endpoints: String,
    },
}

/// The bridge serving the robots; keep it for as long as the viewer runs.
pub struct ZenohRobots {
    bridge: FromZenoh,
}

impl ZenohRobots {
    /// The robots served now, with their loopback ports.
    pub fn serving(&self) -> Vec<(RobotKey, u16)> {
        self.bridge.serving()
    }
}

/// Joins Zenoh (trying the endpoints for up to `wait`), waits up to `wait` for robots (then until discovery has been quiet for a
/// moment), and points `composition` at them: a composition that names servers by their
/// address on the robots' network (`<client host="10.0.0.5" port="6665"/>`) gets those
/// robots; one that names none gets every robot found. Robots that appear later are served
/// by the bridge but not opened by this viewer.
pub fn open_zenoh_robots(
    source: &ZenohSource,
    composition: &mut Composition,
    wait: Duration,
) -> Result<ZenohRobots, ZenohRobotsError> {
    let endpoints = if source.connect.is_empty() {
        "the configured endpoints".to_string()
    } else {
        source.connect.join(", ")
    };
    let join = |source: ZenohError| ZenohRobotsError::Join {
        endpoints: endpoints.clone(),
        source,
    };
    let options = ZenohOptions {
        config_file: source.config_file.clone(),
        // A viewer is a leaf: it reaches Zenoh through the endpoint it was given.
        mode: (!source.connect.is_empty()).then_some(Mode::Client),
        connect: source.connect.clone(),
        listen: Vec::new(),
        no_scouting: false,
        connect_patience: Some(wait),
    };
    let session = options.open().map_err(join)?;
    let identity = source
        .identity
        .clone()
        .unwrap_or_else(|| session.zid().to_string());
    let config = FromZenohConfig::new(&source.site, &identity);
    let bridge = FromZenoh::start(session, config).map_err(join)?;
    let found = wait_for_discovery(&bridge, wait);
    if found.is_empty() {
        return Err(ZenohRobotsError::NoRobots {
            site: source.site.clone(),
            seconds: wait.as_secs_f64(),
            endpoints,
        });
    }
    for (robot, port) in &found {
        tracing::info!(
            "{}/{} is served on 127.0.0.1:{port}",
            robot.site,
            robot.robot
        );
    }
    point_clients_at(composition, &found);
    Ok(ZenohRobots { bridge })
}

/// The robots found: the first within `wait`, then more until none came for [`QUIET`].
fn wait_for_discovery(bridge: &FromZenoh, wait: Duration) -> Vec<(RobotKey, u16)> {
    let deadline = Instant::now() + wait;
    let mut found = bridge.wait_for_robots(1, wait);
    while !found.is_empty() {
        let left = deadline
            .saturating_duration_since(Instant::now())
            .max(QUIET);
        let more = bridge.wait_for_robots(found.len() + 1, QUIET.min(left));
        if more.len() <= found.len() {
            break;
        }
        found = more;
    }
    found
}

/// Points each client the composition names at its robot's loopback port (the robot key is
/// `<host>_<port>` as the robot's relay reaches it); a composition naming none gets all.
fn point_clients_at(composition: &mut Composition, found: &[(RobotKey, u16)]) {
    if composition.clients.is_empty() {
        composition
            .clients
            .extend(found.iter().map(|(_, port)| ClientDecl {
                host: "127.0.0.1".into(),
                port: *port,
                pos: SourcePos::generated(),
            }));
        return;
    }
    for client in &mut composition.clients {
        let named = RobotKey::new("-", &client.host, client.port).robot;
        match found.iter().find(|(robot, _)| robot.robot == named) {
            Some((_, port)) => {
                client.host = "127.0.0.1".into();
                client.port = *port;
            }
            None => tracing::warn!(
                "{}:{} ({}) was not found in Zenoh; its devices stay empty",
                client.host,
                client.port,
                client.pos
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decl(host: &str, port: u16) -> ClientDecl {
        ClientDecl {
            host: host.into(),
            port,
            pos: SourcePos::generated(),
        }
    }

    #[test]
    fn a_composition_naming_no_server_gets_every_robot_found() {
        let mut composition = Composition::default();
        let found = [
            (RobotKey::new("lab", "10.0.0.5", 6665), 40001),
            (RobotKey::new("lab", "10.0.0.5", 6666), 40002),
        ];
        point_clients_at(&mut composition, &found);
        let ports: Vec<_> = composition.clients.iter().map(|c| c.port).collect();
        assert_eq!(ports, [40001, 40002]);
        assert!(composition.clients.iter().all(|c| c.host == "127.0.0.1"));
    }

    #[test]
    fn named_servers_are_found_by_their_address_on_the_robots_network() {
        let mut composition = Composition {
            clients: vec![decl("10.0.0.5", 6666), decl("10.0.0.9", 6665)],
            ..Composition::default()
        };
        let found = [
            (RobotKey::new("lab", "10.0.0.5", 6665), 40001),
            (RobotKey::new("lab", "10.0.0.5", 6666), 40002),
        ];
        point_clients_at(&mut composition, &found);
        assert_eq!(
            (
                composition.clients[0].host.as_str(),
                composition.clients[0].port
            ),
            ("127.0.0.1", 40002)
        );
        // Not in Zenoh: left as written (its devices stay empty, with a warning).
        assert_eq!(composition.clients[1].port, 6665);
    }
}

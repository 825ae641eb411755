//! Serving a recording (`player_proto::recording`) as the Player servers it was recorded from:
//! the same ports (or from a port base), the same devices and driver names, the recorded data
//! at its recorded pace (or faster, paused, stepped, seeked through a `log` device on every
//! port), the recorded replies to the requests that were asked. Commands are refused with a
//! NACK: a recording cannot be steered.

mod clock;
mod devices;
mod playback;

use std::collections::{BTreeMap, HashMap};
use std::net::IpAddr;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::thread::JoinHandle;

use player_proto::recording::{RecordSource, RecordingIndex, SourceError};
use player_proto::server::{Server, ServerConfig, ServerError};
use player_proto::wire::{DevAddr, Interface};

pub use clock::Clock;
use devices::{LogDevice, ReplayedDevice};
use playback::Playback;

/// How a recording is served.
#[derive(Debug, Clone)]
pub struct ReplayOptions {
    pub bind: IpAddr,
    /// Serve the recorded servers on consecutive ports from this one (in order of recorded
    /// port, then host) instead of their own ports; 0 = free ports.
    pub port_base: Option<u16>,
    /// Recorded seconds per real second.
    pub speed: f64,
    /// Start paused (a `log` request or pv3d's timeline starts playback).
    pub paused: bool,
    /// Start again at the end (`readlog`'s `autorewind`).
    pub looping: bool,
}

impl Default for ReplayOptions {
    fn default() -> Self {
        ReplayOptions {
            bind: IpAddr::V4(std::net::Ipv4Addr::LOCALHOST),
            port_base: None,
            speed: 1.0,
            paused: false,
            looping: false,
        }
    }
}

/// Why a recording cannot be served.
#[derive(Debug, thiserror::Error)]
pub enum ReplayError {
    #[error("cannot read {path}: {source}")]
    Read { path: PathBuf, source: SourceError },
    #[error("{path} holds no connection to replay")]
    Empty { path: PathBuf },
    #[error("{a} and {b} were both recorded on port {port}; serve them apart with --port-base")]
    SamePort { port: u16, a: String, b: String },
    #[error("port base {base} leaves no port for the recorded server {server}")]
    NoPort { base: u16, server: String },
    #[error("--speed must be above 0, not {0}")]
    Speed(f64),
    #[error(transparent)]
    Server(#[from] ServerError),
}

/// One recorded server, as served.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ServedRecording {
    pub host: String,
    pub recorded_port: u16,
    /// The port it is served on now.
    pub port: u16,
    /// The `log` device controlling playback on that port.
    pub log: DevAddr,
}

/// A recording being served; stops when dropped.
pub struct Replaying {
    pub servers: Vec<ServedRecording>,
    pub clock: Arc<Clock>,
    /// Why reading the recording stopped before its end (a torn tail): playback ends there.
    pub stopped: Option<SourceError>,
    thread: Option<JoinHandle<()>>,
    _server: Server,
}

impl Replaying {
    /// Serves until the process ends.
    pub fn wait(mut self) {
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

impl Drop for Replaying {
    fn drop(&mut self) {
        self.clock.stop();
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// Reads the recording (a `.prec`, or an MCAP file written from one) once for its servers and
/// devices, then serves it.
pub fn replay(path: &Path, options: &ReplayOptions) -> Result<Replaying, ReplayError> {
    let read_error = |source| ReplayError::Read {
        path: path.to_path_buf(),
        source,
    };
    let source = player_mcap::open_recording(path).map_err(read_error)?;
    replay_source(Arc::from(source), path, options)
}

/// Serves the recording `source` holds; `path` names it in errors.
pub fn replay_source(
    source: Arc<dyn RecordSource>,
    path: &Path,
    options: &ReplayOptions,
) -> Result<Replaying, ReplayError> {
    if !(options.speed > 0.0 && options.speed.is_finite()) {
        return Err(ReplayError::Speed(options.speed));
    }
    let read_error = |source| ReplayError::Read {
        path: path.to_path_buf(),
        source,
    };
    let index = RecordingIndex::read(&*source).map_err(read_error)?;
    if let Some(e) = &index.stopped
        && !e.is_torn_tail()
    {
        tracing::warn!("{}: replaying up to the damage: {e}", path.display());
    }

    // One server per recorded host:port; several connections to it (reconnections, or two
    // clients) share it.
    let mut servers: BTreeMap<(u16, String), Vec<u32>> = BTreeMap::new();
    for (&number, c) in &index.connections {
        servers
            .entry((c.port, c.host.clone()))
            .or_default()
            .push(number);
    }
    if servers.is_empty() {
        return Err(ReplayError::Empty {
            path: path.to_path_buf(),
        });
    }
    let served_ports = choose_ports(&servers, options.port_base)?;

    let clock = Arc::new(Clock::new(
        index.last_ns.saturating_sub(index.first_ns),
        options.speed,
        !options.paused,
    ));
    let mut config = ServerConfig::default();
    config.bind = options.bind;
    if let Some(version) = index.connections.values().find_map(|c| c.version()) {
        config.version = version;
    }
    let mut robots = Vec::new();
    let mut log_indices = Vec::new();
    for (((_, host), numbers), &port) in servers.iter().zip(&served_ports) {
        let robot = config.robot(port);
        robots.push(robot);
        let mut devices = BTreeMap::new();
        let mut replies = HashMap::new();
        for number in numbers {
            let c = &index.connections[number];
            for (key, driver) in &c.devices {
                let known: &mut String = devices.entry(*key).or_default();
                if known.is_empty() {
                    known.clone_from(driver);
                }
            }
            replies.extend(c.replies.iter().map(|(k, v)| (k.clone(), v.clone())));
        }
        let replies = Arc::new(replies);
        for (&(interf, index), driver) in &devices {
            let device = ReplayedDevice {
                driver: if driver.is_empty() {
                    "readlog".into()
                } else {
                    driver.clone()
                },
                replies: replies.clone(),
            };
            config.device(robot, DevAddr::local(interf, index), device);
        }
        let log_index = devices
            .keys()
            .filter(|(interf, _)| *interf == Interface::LOG)
            .map(|&(_, index)| index + 1)
            .max()
            .unwrap_or(0);
        let log = LogDevice {
            clock: clock.clone(),
        };
        config.device(robot, DevAddr::local(Interface::LOG, log_index), log);
        log_indices.push(log_index);
        tracing::debug!(host, port, "{} recorded devices", devices.len());
    }
    let server = Server::start(config)?;

    let mut connection_ports = HashMap::new();
    let mut served = Vec::new();
    for (((recorded_port, host), numbers), (robot, log_index)) in
        servers.iter().zip(robots.into_iter().zip(log_indices))
    {
        let port = server.port(robot);
        for &number in numbers {
            connection_ports.insert(number, port);
        }
        let mut log = DevAddr::local(Interface::LOG, log_index);
        log.robot = u32::from(port);
        served.push(ServedRecording {
            host: host.clone(),
            recorded_port: *recorded_port,
            port,
            log,
        });
    }
    let playback = Playback {
        source,
        clock: clock.clone(),
        publisher: server.publisher(),
        ports: connection_ports,
        log_devices: served.iter().map(|s| s.log).collect(),
        seek_points: index.seek_points.clone(),
        first_ns: index.first_ns,
        looping: options.looping,
    };
    let thread = std::thread::Builder::new()
        .name("player-sim replay".into())
        .spawn(move || playback.run())
        .map_err(|e| ReplayError::Server(ServerError::Runtime(e)))?;
    Ok(Replaying {
        servers: served,
        clock,
        stopped: index.stopped,
        thread: Some(thread),
        _server: server,
    })
}

/// The port each recorded server is served on, in the map's order.
fn choose_ports(
    servers: &BTreeMap<(u16, String), Vec<u32>>,
    base: Option<u16>,
) -> Result<Vec<u16>, ReplayError> {
    let name = |(port, host): &(u16, String)| format!("{host}:{port}");
    match base {
        Some(0) => Ok(vec![0; servers.len()]),
        Some(base) => servers
            .keys()
            .enumerate()
            .map(|(i, key)| {
                u16::try_from(i)
                    .ok()
                    .and_then(|i| base.checked_add(i))
                    .ok_or_else(|| ReplayError::NoPort {
                        base,
                        server: name(key),
                    })
            })
            .collect(),
        None => {
            let keys: Vec<_> = servers.keys().collect();
            if let Some(pair) = keys.windows(2).find(|w| w[0].0 == w[1].0) {
                return Err(ReplayError::SamePort {
                    port: pair[0].0,
                    a: name(pair[0]),
                    b: name(pair[1]),
                });
            }
            Ok(keys.iter().map(|(port, _)| *port).collect())
        }
    }
}

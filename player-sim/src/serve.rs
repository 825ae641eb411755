//! Serving a simulation: a Player server with one port per robot, and a thread that steps the
//! world at `interval_sim` (scaled by the speedup) and publishes each subscribed device's data.

use std::net::IpAddr;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use player_proto::server::{DeviceKey, Server, ServerConfig, ServerError};
use player_proto::wire::DevAddr;

use crate::devices::SimDevice;
use crate::served::{ServedDevice, attach_navigation, devices_beside};
use crate::sim::Simulation;
use crate::world::World;
use crate::worldfile::WorldFileError;

/// How a simulation is served.
#[derive(Debug, Clone)]
pub struct ServeOptions {
    pub bind: IpAddr,
    /// Simulated seconds per real second; 0 runs as fast as the machine can.
    pub speedup: f64,
    /// Stop after this many steps (for tests and benchmarks).
    pub max_steps: Option<u64>,
    /// Serve on free ports chosen by the system instead of the configured ones.
    pub free_ports: bool,
}

impl Default for ServeOptions {
    fn default() -> Self {
        ServeOptions {
            bind: IpAddr::V4(std::net::Ipv4Addr::LOCALHOST),
            speedup: 1.0,
            max_steps: None,
            free_ports: false,
        }
    }
}

/// A simulation being served; stops when dropped.
pub struct Running {
    pub sim: Arc<Mutex<Simulation>>,
    /// (configured port, port actually served on).
    pub ports: Vec<(u16, u16)>,
    stop: Arc<AtomicBool>,
    stepper: Option<JoinHandle<()>>,
    _server: Server,
}

impl Running {
    /// The port a configured port is served on.
    pub fn port(&self, configured: u16) -> Option<u16> {
        self.ports
            .iter()
            .find(|(c, _)| *c == configured)
            .map(|(_, a)| *a)
    }

    /// Waits until the stepping thread ends (after `max_steps`, or never).
    pub fn wait(mut self) {
        if let Some(t) = self.stepper.take() {
            let _ = t.join();
        }
    }

    pub fn stop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(t) = self.stepper.take() {
            let _ = t.join();
        }
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        self.stop();
    }
}

/// Why a world file could not be served.
#[derive(Debug, thiserror::Error)]
pub enum ServeWorldError {
    #[error(transparent)]
    World(#[from] WorldFileError),
    #[error(transparent)]
    Serve(#[from] ServerError),
}

/// Serves the world at `path` with the devices its .cfg files name
/// ([`devices_beside`]). A configured port listed in `moved` is served on the port it maps
/// to (a server restarted where it was); what the files ask that is not simulated is added
/// to `ignored`.
pub fn serve_world_file(
    path: &std::path::Path,
    options: ServeOptions,
    moved: &[(u16, u16)],
    ignored: &mut Vec<String>,
) -> Result<Running, ServeWorldError> {
    let world = World::load(path)?;
    let mut devices = devices_beside(path, &world, ignored)?;
    for device in &mut devices {
        if let Some(&(_, actual)) = moved.iter().find(|(c, _)| *c == device.port) {
            device.port = actual;
        }
    }
    Ok(serve(Simulation::new(world), devices, options)?)
}

/// Starts serving `sim` with `devices`.
pub fn serve(
    sim: Simulation,
    devices: Vec<ServedDevice>,
    options: ServeOptions,
) -> Result<Running, ServerError> {
    let mut sim = sim;
    attach_navigation(&mut sim, &devices);
    let sim = Arc::new(Mutex::new(sim));
    let mut configured: Vec<u16> = devices.iter().map(|d| d.port).collect();
    configured.sort_unstable();
    configured.dedup();
    let mut config = ServerConfig::default();
    config.bind = options.bind;
    // One thread publishes every robot's data each step: it writes to the sockets itself.
    config.publisher_writes = true;
    let robots: Vec<usize> = configured
        .iter()
        .map(|&p| config.robot(if options.free_ports { 0 } else { p }))
        .collect();
    for d in &devices {
        let robot = robots[configured.binary_search(&d.port).expect("collected above")];
        config.device(
            robot,
            d.addr(),
            SimDevice {
                sim: sim.clone(),
                served: d.clone(),
            },
        );
    }
    let server = Server::start(config)?;
    let ports: Vec<(u16, u16)> = configured
        .iter()
        .zip(&robots)
        .map(|(&c, &r)| (c, server.port(r)))
        .collect();
    // Each device found once in the server: the step asks after every one at every step.
    let publisher = server.publisher();
    let published: Vec<(DeviceKey, crate::served::Source)> = devices
        .iter()
        .filter_map(|d| {
            let actual = ports
                .iter()
                .find(|(c, _)| *c == d.port)
                .map_or(d.port, |(_, a)| *a);
            let addr = DevAddr {
                robot: u32::from(actual),
                ..d.addr()
            };
            Some((publisher.find(addr)?, d.source.clone()))
        })
        .collect();
    let stop = Arc::new(AtomicBool::new(false));
    let stepper = {
        let (sim, stop) = (sim.clone(), stop.clone());
        std::thread::Builder::new()
            .name("player-sim step".into())
            .spawn(move || step_loop(&sim, &published, &publisher, &options, &stop))
            .expect("spawning the simulation thread")
    };
    Ok(Running {
        sim,
        ports,
        stop,
        stepper: Some(stepper),
        _server: server,
    })
}

fn step_loop(
    sim: &Mutex<Simulation>,
    devices: &[(DeviceKey, crate::served::Source)],
    publisher: &player_proto::server::Publisher,
    options: &ServeOptions,
    stop: &AtomicBool,
) {
    let interval = sim.lock().expect("simulation").world.interval;
    let period = if options.speedup > 0.0 {
        Some(Duration::from_secs_f64(interval / options.speedup))
    } else {
        None
    };
    let started = Instant::now();
    let mut steps = 0u64;
    while !stop.load(Ordering::Relaxed) && options.max_steps.is_none_or(|max| steps < max) {
        let outgoing: Vec<_> = {
            let mut sim = sim.lock().expect("simulation");
            sim.step();
            let id = u32::try_from(sim.steps).unwrap_or(u32::MAX);
            // The step's scans in one sensing scope: the robots' index is checked once.
            sim.sensing(|sim| {
                devices
                    .iter()
                    .filter(|(key, _)| publisher.subscribers_of(*key) > 0)
                    .flat_map(|(key, source)| {
                        let key = *key;
                        SimDevice::data(sim, source, id)
                            .into_iter()
                            .map(move |(subtype, body)| (key, source, subtype, body))
                    })
                    .map(|(key, source, subtype, body)| {
                        let time = if source.stamped_by_wall_clock() {
                            wall_clock()
                        } else {
                            sim.time
                        };
                        (key, subtype, body, time)
                    })
                    .collect()
            })
        };
        publisher.publish_to_all(outgoing);
        steps += 1;
        if let Some(period) = period {
            let due = started + period.mul_f64(steps as f64);
            if let Some(wait) = due.checked_duration_since(Instant::now()) {
                std::thread::sleep(wait);
            }
        }
    }
}

/// Seconds since the Unix epoch, as Player's server clock reads.
fn wall_clock() -> f64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0.0, |d| d.as_secs_f64())
}

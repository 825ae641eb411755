//! Serving a simulation: a Player server with one port per robot, and a thread that steps the
//! world at `interval_sim` (scaled by the speedup) and publishes each subscribed device's data.

use std::net::IpAddr;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;

use player_proto::server::{Lockstep, Server, ServerConfig, ServerError};
use player_proto::wire::DevAddr;

use crate::devices::SimDevice;
pub use crate::serve_options::{LockstepOptions, ServeOptions};
use crate::served::{ServedDevice, attach_navigation, devices_beside};
use crate::sim::Simulation;
use crate::sim_record::PortRecord;
use crate::stepper::{Published, step_loop};
use crate::world::World;
use crate::worldfile::WorldFileError;

/// A simulation being served; stops when dropped.
pub struct Running {
    pub sim: Arc<Mutex<Simulation>>,
    /// (configured port, port actually served on).
    pub ports: Vec<(u16, u16)>,
    /// The turnstile of a lockstep simulation.
    pub lockstep: Option<Arc<Lockstep>>,
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

    /// Whether the stepping thread has ended (after `max_steps`).
    pub fn finished(&self) -> bool {
        self.stepper.as_ref().is_none_or(JoinHandle::is_finished)
    }

    /// Waits until the stepping thread ends (after `max_steps`, or never).
    pub fn wait(mut self) {
        if let Some(t) = self.stepper.take() {
            let _ = t.join();
        }
    }

    pub fn stop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(lockstep) = &self.lockstep {
            lockstep.release(1);
        }
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
    let lockstep = options
        .lockstep
        .map(|l| Arc::new(Lockstep::new(l.patience)));
    config.lockstep = lockstep.clone();
    let robots: Vec<usize> = configured
        .iter()
        .map(|&p| config.robot(if options.free_ports { 0 } else { p }))
        .collect();
    // The recording names ports as configured, so that it does not depend on free ports.
    let order = Arc::new(Mutex::new(()));
    let host = options.bind.to_string();
    let records: Vec<Option<PortRecord>> = configured
        .iter()
        .map(|&port| {
            options
                .record
                .as_ref()
                .map(|r| PortRecord::open(r, &host, port, order.clone()))
        })
        .collect();
    let slot = |port: u16| configured.binary_search(&port).expect("collected above");
    for d in &devices {
        let at = slot(d.port);
        config.device(
            robots[at],
            d.addr(),
            SimDevice {
                sim: sim.clone(),
                served: d.clone(),
                record: records[at]
                    .clone()
                    .map(|r| (r, recorded_addr(d, options.bind))),
                greets: options.lockstep.is_some(),
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
    let published: Vec<Published> = devices
        .iter()
        .filter_map(|d| {
            let at = slot(d.port);
            let addr = DevAddr {
                robot: u32::from(ports[at].1),
                ..d.addr()
            };
            Some(Published {
                key: publisher.find(addr)?,
                source: d.source.clone(),
                record: records[at]
                    .clone()
                    .map(|r| (r, recorded_addr(d, options.bind))),
            })
        })
        .collect();
    let stop = Arc::new(AtomicBool::new(false));
    let stepper = {
        let (sim, stop) = (sim.clone(), stop.clone());
        std::thread::Builder::new()
            .name("player-sim step".into())
            .spawn({
                let lockstep = lockstep.clone();
                move || {
                    step_loop(
                        &sim,
                        &published,
                        &publisher,
                        &options,
                        lockstep.as_deref(),
                        &stop,
                    )
                }
            })
            .expect("spawning the simulation thread")
    };
    Ok(Running {
        sim,
        ports,
        lockstep,
        stop,
        stepper: Some(stepper),
        _server: server,
    })
}

/// A device's address in the simulation's recording: the served host, the configured port.
fn recorded_addr(device: &ServedDevice, bind: IpAddr) -> DevAddr {
    let ip = match bind {
        IpAddr::V4(ip) if !ip.is_unspecified() => ip,
        _ => std::net::Ipv4Addr::LOCALHOST,
    };
    DevAddr {
        host: DevAddr::host_from_ipv4(ip),
        ..device.addr()
    }
}

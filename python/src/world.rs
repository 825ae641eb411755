//! `player3.simulate(world_file)`: player-sim in this process, serving a Stage world on free
//! local ports, so a notebook or a test needs no server of its own. Robots are reached over
//! real TCP like any Player server.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use player_proto::RobotId;
use player_sim::serve::{LockstepOptions, Running, ServeOptions, serve};
use player_sim::served::{Source, devices_beside};
use player_sim::sim::Simulation;
use player_sim::world::World as WorldFile;
use pyo3::exceptions::{PyKeyError, PyTypeError, PyValueError};
use pyo3::prelude::*;

use crate::errors::PlayerError;
use crate::link::Link;
use crate::robot::Robot;
use crate::waiting::timeout_arg;

/// A served port and the names of the robots on it.
type PortRobots = (u16, Vec<String>);

/// A simulated world being served. Use it in a `with` block, or call `close()`.
#[pyclass(frozen, module = "player3")]
pub struct World {
    running: Mutex<Option<Running>>,
    /// Served ports in configured order, with the robot names on each.
    robots: Vec<PortRobots>,
    /// The world file served.
    #[pyo3(get)]
    path: PathBuf,
}

/// Serves the world file (with the `.cfg` files beside it, as player-sim does) on free local
/// ports. `speedup` is simulated seconds per real second (0: as fast as possible; by default
/// 1, and 0 in lockstep, where the programs set the pace).
/// `lockstep=True` takes a step once every client driving a robot has sent its command for
/// it (or `World.step()` says so), waiting at most `patience` seconds for one (None: for
/// ever); `seed` draws the noise and the wander controller's turns.
#[pyfunction]
#[pyo3(signature = (world, speedup = None, lockstep = false, patience = Some(5.0), seed = 0))]
pub fn simulate(
    py: Python<'_>,
    world: PathBuf,
    speedup: Option<f64>,
    lockstep: bool,
    patience: Option<f64>,
    seed: u64,
) -> PyResult<World> {
    let speedup = speedup.unwrap_or(if lockstep { 0.0 } else { 1.0 });
    if !(speedup >= 0.0 && speedup.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "speedup must be 0 or more, got {speedup}"
        )));
    }
    let patience = match patience {
        Some(p) if p > 0.0 && p.is_finite() => Some(Duration::from_secs_f64(p)),
        None => None,
        Some(p) => {
            return Err(PyValueError::new_err(format!(
                "patience must be more than 0 seconds (or None: for ever), got {p}"
            )));
        }
    };
    let options = ServeOptions {
        speedup,
        free_ports: true,
        lockstep: lockstep.then_some(LockstepOptions { patience }),
        ..ServeOptions::default()
    };
    let path = world.clone();
    let (running, robots) = py.detach(move || start(&world, options, seed))?;
    Ok(World {
        running: Mutex::new(Some(running)),
        robots,
        path,
    })
}

fn start(path: &Path, options: ServeOptions, seed: u64) -> PyResult<(Running, Vec<PortRobots>)> {
    let failed = |e: &dyn std::fmt::Display| {
        PlayerError::new_err(format!("cannot simulate {}: {e}", path.display()))
    };
    if !path.is_file() {
        return Err(pyo3::exceptions::PyFileNotFoundError::new_err(format!(
            "no world file at {}",
            path.display()
        )));
    }
    let world = WorldFile::load(path).map_err(|e| failed(&e))?;
    let mut ignored = world.ignored.clone();
    // The .cfg files beside the world, as player-sim reads them (one port per robot when there
    // are none, or when they name models the world lacks).
    let devices = devices_beside(path, &world, &mut ignored).map_err(|e| failed(&e))?;
    let mut names: BTreeMap<u16, Vec<String>> = BTreeMap::new();
    for d in &devices {
        let entry = names.entry(d.port).or_default();
        // A robot is named on its own port, not where a passthrough (a navigation port)
        // forwards its base.
        if let Source::Position { robot } = d.source
            && d.driver != "passthrough"
            && let Some(spec) = world.robots.get(robot)
            && !entry.contains(&spec.name)
        {
            entry.push(spec.name.clone());
        }
    }
    let mut sim = Simulation::new(world);
    sim.noise.seed = seed;
    let running = serve(sim, devices, options).map_err(|e| failed(&e))?;
    let robots = names
        .into_iter()
        .map(|(configured, names)| (running.port(configured).unwrap_or(configured), names))
        .collect();
    Ok((running, robots))
}

impl World {
    fn port_of(&self, which: &Bound<'_, PyAny>) -> PyResult<u16> {
        if let Ok(index) = which.extract::<i64>() {
            let found = usize::try_from(index).ok().and_then(|i| self.robots.get(i));
            return found.map(|(port, _)| *port).ok_or_else(|| {
                PyKeyError::new_err(format!(
                    "robot index {index}: {} serves {} robots",
                    self.path.display(),
                    self.robots.len()
                ))
            });
        }
        if let Ok(name) = which.extract::<String>() {
            return self
                .robots
                .iter()
                .find(|(_, names)| names.contains(&name))
                .map(|(port, _)| *port)
                .ok_or_else(|| {
                    PyKeyError::new_err(format!(
                        "no robot named {name:?} in {} (it has {:?})",
                        self.path.display(),
                        self.names()
                    ))
                });
        }
        Err(PyTypeError::new_err(
            "a robot is named by its name (str) or its index (int)",
        ))
    }

    fn names(&self) -> Vec<String> {
        self.robots.iter().flat_map(|(_, n)| n.clone()).collect()
    }

    /// The simulation's lockstep turnstile and clock, while it is served.
    fn served<R>(&self, f: impl FnOnce(&Running) -> R) -> PyResult<R> {
        let running = self.running.lock().unwrap_or_else(|e| e.into_inner());
        match running.as_ref() {
            Some(running) => Ok(f(running)),
            None => Err(PlayerError::new_err(format!(
                "the simulation of {} was closed",
                self.path.display()
            ))),
        }
    }
}

#[pymethods]
impl World {
    /// A connected `Robot`: by name (`"r0"`) or by index (0: the first port served).
    #[pyo3(signature = (which = None, timeout = 5.0, read_only = false))]
    fn robot(
        &self,
        py: Python<'_>,
        which: Option<Bound<'_, PyAny>>,
        timeout: f64,
        read_only: bool,
    ) -> PyResult<Robot> {
        let which = match which {
            Some(which) => which,
            None => 0i64.into_pyobject(py)?.into_any(),
        };
        let port = self.port_of(&which)?;
        // Asked by name, it is that robot; by index, the port's first (its only, mostly).
        let name = match which.extract::<String>() {
            Ok(name) => Some(name),
            Err(_) => self
                .robots
                .iter()
                .find(|(p, _)| *p == port)
                .and_then(|(_, names)| names.first().cloned()),
        };
        // A model's name the fronts could not carry (a space in it) leaves the robot unnamed.
        let unnamed = RobotId::new("127.0.0.1", port);
        let id = name
            .and_then(|n| unnamed.clone().named(n).ok())
            .unwrap_or(unnamed);
        let limit = timeout_arg(timeout, "connecting to the simulated world")?;
        let link = Link::connect(py, "127.0.0.1", port, limit, read_only)?;
        Ok(Robot::new(id, link))
    }

    /// The names of the robots (those with a `position2d`), in port order.
    fn robots(&self) -> Vec<String> {
        self.names()
    }

    /// Whether the world steps in lockstep with its driving clients.
    #[getter]
    fn lockstep(&self) -> PyResult<bool> {
        self.served(|r| r.lockstep.is_some())
    }

    /// Simulated seconds so far.
    #[getter]
    fn time(&self) -> PyResult<f64> {
        self.served(|r| r.sim.lock().map_or(0.0, |sim| sim.time))
    }

    /// Lockstep: takes `steps` steps now, without waiting for the clients that drive robots,
    /// and returns the simulated time once they are taken (their data published). For a
    /// program that reads without commanding; a command is a client's own turn already.
    #[pyo3(signature = (steps = 1, timeout = 10.0))]
    fn step(&self, py: Python<'_>, steps: i64, timeout: f64) -> PyResult<f64> {
        let steps = u64::try_from(steps)
            .ok()
            .filter(|&s| s > 0)
            .ok_or_else(|| {
                PyValueError::new_err(format!("steps must be 1 or more, got {steps}"))
            })?;
        let limit = timeout_arg(timeout, "stepping the world")?;
        let Some(lockstep) = self.served(|r| r.lockstep.clone())? else {
            return Err(PlayerError::new_err(format!(
                "{} is not simulated in lockstep: it steps by itself (simulate(..., lockstep=True))",
                self.path.display()
            )));
        };
        let target = lockstep.steps() + steps;
        lockstep.release(steps);
        let deadline = Instant::now() + limit;
        loop {
            let slice = deadline
                .saturating_duration_since(Instant::now())
                .min(Duration::from_millis(50));
            if py.detach(|| lockstep.wait_for_step(target, slice)) {
                return self.time();
            }
            py.check_signals()?;
            if Instant::now() >= deadline {
                return Err(pyo3::exceptions::PyTimeoutError::new_err(format!(
                    "stepping {}: {steps} step(s) not taken within {timeout} s",
                    self.path.display()
                )));
            }
        }
    }

    /// The local ports served, one per configured Player port.
    #[getter]
    fn ports(&self) -> Vec<u16> {
        self.robots.iter().map(|(port, _)| *port).collect()
    }

    /// Stops the simulation and its server.
    fn close(&self, py: Python<'_>) {
        let running = self
            .running
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .take();
        py.detach(move || drop(running));
    }

    fn __enter__(slf: Py<Self>) -> Py<Self> {
        slf
    }

    fn __exit__(
        &self,
        py: Python<'_>,
        _kind: Option<Bound<'_, PyAny>>,
        _value: Option<Bound<'_, PyAny>>,
        _traceback: Option<Bound<'_, PyAny>>,
    ) -> bool {
        self.close(py);
        false
    }

    fn __repr__(&self) -> String {
        format!(
            "<World {} serving {:?} on ports {:?}>",
            self.path.display(),
            self.names(),
            self.ports()
        )
    }
}

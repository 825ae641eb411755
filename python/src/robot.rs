//! `player3.connect(...)` and the `Robot` it returns: one Player server connection, its device
//! list, and a typed object per device.

use std::sync::{Arc, Mutex};

use player_proto::RobotId;
use player_proto::wire::Interface;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::camera::Camera;
use crate::errors::ConnectionError;
use crate::link::{DeviceCore, Link};
use crate::map::Map;
use crate::navigation::{Localize, Planner, Speech};
use crate::position::Position2d;
use crate::rangers::{Laser, Ranger, Sonar};
use crate::sensors::{Blobfinder, Bumper, Fiducial, Gripper, Power};
use crate::waiting::{timeout_arg, wait_for};

/// A device the server offers: `interface` (`"laser"`), `index`, and the `driver` behind it.
#[pyclass(frozen, get_all, eq, module = "player3")]
#[derive(Clone, PartialEq)]
pub struct Device {
    pub interface: String,
    pub index: u16,
    pub driver: String,
}

#[pymethods]
impl Device {
    fn __repr__(&self) -> String {
        format!(
            "Device(interface={:?}, index={}, driver={:?})",
            self.interface, self.index, self.driver
        )
    }
}

/// Connects to the Player server at `host:port`, waiting at most `timeout` seconds.
/// `read_only=True` observes: commands and configuration requests raise `PermissionError`.
/// Without a host or port, `PLAYER_HOST` and `PLAYER_PORT` from the environment are used
/// (a grader sets them for the program it runs), else localhost and 6665.
/// `name` names the robot as the relay's fronts and logs name it (`"r0"`; letters, digits,
/// `_`, `-`, `.`); without one it goes by `host:port`.
#[pyfunction]
#[pyo3(signature = (host = None, port = None, timeout = 5.0, read_only = false, name = None))]
pub fn connect(
    py: Python<'_>,
    host: Option<String>,
    port: Option<i64>,
    timeout: f64,
    read_only: bool,
    name: Option<String>,
) -> PyResult<Robot> {
    let host = match host {
        Some(host) => host,
        None => std::env::var("PLAYER_HOST").unwrap_or_else(|_| "localhost".into()),
    };
    let port = match port {
        Some(port) => port,
        None => match std::env::var("PLAYER_PORT") {
            Ok(text) => text.trim().parse::<i64>().map_err(|_| {
                PyValueError::new_err(format!("PLAYER_PORT must be a port number, got {text:?}"))
            })?,
            Err(_) => 6665,
        },
    };
    let host = host.as_str();
    let port = u16::try_from(port)
        .ok()
        .filter(|&p| p != 0)
        .ok_or_else(|| PyValueError::new_err(format!("port must be 1 to 65535, got {port}")))?;
    let id = robot_id(host, port, name)?;
    let limit = timeout_arg(timeout, &format!("connecting to {host}:{port}"))?;
    if limit.is_zero() {
        return Err(PyValueError::new_err(format!(
            "connecting to {host}:{port}: a timeout of 0 leaves no time for the handshake"
        )));
    }
    let link = Link::connect(py, host, port, limit, read_only)?;
    Ok(Robot::new(id, link))
}

/// The robot at `host:port`, named `name` where given: a name the fronts could not carry is
/// a `ValueError` naming it.
pub fn robot_id(host: &str, port: u16, name: Option<String>) -> PyResult<RobotId> {
    let id = RobotId::new(host, port);
    match name {
        None => Ok(id),
        Some(name) => id
            .named(name)
            .map_err(|e| PyValueError::new_err(e.to_string())),
    }
}

/// A connection to one Player server (one robot). Use it in a `with` block, or call
/// `close()`. Device objects come from methods named after their interface.
#[pyclass(frozen, module = "player3")]
pub struct Robot {
    /// Who it is, as every front and log says it.
    id: RobotId,
    link: Mutex<Option<Arc<Link>>>,
}

impl Robot {
    pub fn new(id: RobotId, link: Arc<Link>) -> Robot {
        Robot {
            id,
            link: Mutex::new(Some(link)),
        }
    }

    fn link(&self) -> PyResult<Arc<Link>> {
        self.link
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
            .ok_or_else(|| ConnectionError::new_err("this Robot was closed"))
    }

    fn open(&self, py: Python<'_>, interf: Interface, index: i64) -> PyResult<DeviceCore> {
        self.link()?.open(py, interf, index)
    }
}

#[pymethods]
impl Robot {
    /// The devices the server offers.
    fn devices(&self) -> PyResult<Vec<Device>> {
        let link = self.link()?;
        Ok(link
            .client
            .devices()
            .into_iter()
            .map(|d| Device {
                interface: d.addr.interf.name().unwrap_or("unknown").to_string(),
                index: d.addr.index,
                driver: d.driver,
            })
            .collect())
    }

    /// `host:port` of the server.
    #[getter]
    fn address(&self) -> PyResult<String> {
        Ok(self.link()?.place.clone())
    }

    /// The robot's name (the world's, or the one given to `connect`), else `None`.
    #[getter]
    fn name(&self) -> Option<String> {
        self.id.name().map(str::to_string)
    }

    /// The robot as the relay's fronts and logs say it: its name, else `host:port`.
    fn __str__(&self) -> String {
        self.id.to_string()
    }

    /// Whether the connection is up now (it comes back by itself after a server restart).
    #[getter]
    fn connected(&self) -> PyResult<bool> {
        Ok(self.link()?.is_connected())
    }

    /// Waits until the connection is up (again), at most `timeout` s; `TimeoutError` if not.
    #[pyo3(signature = (timeout = 10.0))]
    fn wait_connected(&self, py: Python<'_>, timeout: f64) -> PyResult<()> {
        let link = self.link()?;
        let limit = timeout_arg(timeout, "wait_connected")?;
        let what = format!("reconnecting to {}", link.place);
        wait_for(
            py,
            &link.wakeup,
            limit,
            &what,
            || link.is_connected().then_some(()),
            || Ok(()),
        )
    }

    /// The mobile base `position2d:index`.
    #[pyo3(signature = (index = 0))]
    fn position2d(&self, py: Python<'_>, index: i64) -> PyResult<Position2d> {
        let core = self.open(py, Interface::POSITION2D, index)?;
        Ok(Position2d { core })
    }

    /// The laser `laser:index`.
    #[pyo3(signature = (index = 0))]
    fn laser(&self, py: Python<'_>, index: i64) -> PyResult<Laser> {
        let core = self.open(py, Interface::LASER, index)?;
        Ok(Laser { core })
    }

    /// The range sensor `ranger:index`.
    #[pyo3(signature = (index = 0))]
    fn ranger(&self, py: Python<'_>, index: i64) -> PyResult<Ranger> {
        let core = self.open(py, Interface::RANGER, index)?;
        Ranger::open(py, core)
    }

    /// The sonar ring `sonar:index`.
    #[pyo3(signature = (index = 0))]
    fn sonar(&self, py: Python<'_>, index: i64) -> PyResult<Sonar> {
        let core = self.open(py, Interface::SONAR, index)?;
        Sonar::open(py, core)
    }

    /// The fiducial finder `fiducial:index`.
    #[pyo3(signature = (index = 0))]
    fn fiducial(&self, py: Python<'_>, index: i64) -> PyResult<Fiducial> {
        let core = self.open(py, Interface::FIDUCIAL, index)?;
        Ok(Fiducial { core })
    }

    /// The camera `camera:index`.
    #[pyo3(signature = (index = 0))]
    fn camera(&self, py: Python<'_>, index: i64) -> PyResult<Camera> {
        let core = self.open(py, Interface::CAMERA, index)?;
        Ok(Camera { core })
    }

    /// The map `map:index`.
    #[pyo3(signature = (index = 0))]
    fn map(&self, py: Python<'_>, index: i64) -> PyResult<Map> {
        let core = self.open(py, Interface::MAP, index)?;
        Ok(Map { core })
    }

    /// The localizer `localize:index`.
    #[pyo3(signature = (index = 0))]
    fn localize(&self, py: Python<'_>, index: i64) -> PyResult<Localize> {
        let core = self.open(py, Interface::LOCALIZE, index)?;
        Ok(Localize { core })
    }

    /// The path planner `planner:index`.
    #[pyo3(signature = (index = 0))]
    fn planner(&self, py: Python<'_>, index: i64) -> PyResult<Planner> {
        let core = self.open(py, Interface::PLANNER, index)?;
        Ok(Planner { core })
    }

    /// The speech device `speech:index`.
    #[pyo3(signature = (index = 0))]
    fn speech(&self, py: Python<'_>, index: i64) -> PyResult<Speech> {
        let core = self.open(py, Interface::SPEECH, index)?;
        Ok(Speech { core })
    }

    /// The blob finder `blobfinder:index`.
    #[pyo3(signature = (index = 0))]
    fn blobfinder(&self, py: Python<'_>, index: i64) -> PyResult<Blobfinder> {
        let core = self.open(py, Interface::BLOBFINDER, index)?;
        Ok(Blobfinder { core })
    }

    /// The bumpers `bumper:index`.
    #[pyo3(signature = (index = 0))]
    fn bumper(&self, py: Python<'_>, index: i64) -> PyResult<Bumper> {
        let core = self.open(py, Interface::BUMPER, index)?;
        Ok(Bumper { core })
    }

    /// The power pack `power:index`.
    #[pyo3(signature = (index = 0))]
    fn power(&self, py: Python<'_>, index: i64) -> PyResult<Power> {
        let core = self.open(py, Interface::POWER, index)?;
        Ok(Power { core })
    }

    /// The gripper `gripper:index`.
    #[pyo3(signature = (index = 0))]
    fn gripper(&self, py: Python<'_>, index: i64) -> PyResult<Gripper> {
        let core = self.open(py, Interface::GRIPPER, index)?;
        Ok(Gripper { core })
    }

    /// Closes the connection (once the device objects taken from it are gone too).
    fn close(&self, py: Python<'_>) {
        let link = self.link.lock().unwrap_or_else(|e| e.into_inner()).take();
        // Dropping the last handle joins the robot thread: not with the GIL held.
        py.detach(move || drop(link));
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
        // A named robot says where it is served too; an unnamed one is its address.
        let who = match self.id.name() {
            Some(name) => format!("{name} at {}", self.id.server()),
            None => self.id.server(),
        };
        match self.link() {
            Ok(link) => format!(
                "<Robot {who} ({}, {} devices)>",
                if link.is_connected() {
                    "connected"
                } else {
                    "not connected"
                },
                link.client.devices().len()
            ),
            Err(_) => format!("<Robot {who} (closed)>"),
        }
    }

    /// A table of the devices, their drivers, and how much each has sent, for Jupyter.
    fn _repr_html_(&self) -> PyResult<String> {
        crate::robot_table::html(&*self.link()?)
    }
}

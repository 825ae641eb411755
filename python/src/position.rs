//! `robot.position2d(i)`: a mobile base — odometry in, velocity and position commands out.

use std::time::{Duration, Instant};

use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::position2d::{
    Position2d as Messages, Position2dCmdPos, Position2dCmdVel, Position2dData, Position2dPower,
};
use pyo3::exceptions::PyTimeoutError;
use pyo3::prelude::*;

use crate::link::DeviceCore;
use crate::waiting::{timeout_arg, wait_for};

/// How long a property waits for the first odometry after subscribing.
const FIRST_READING: Duration = Duration::from_secs(2);

/// A `position2d` device: odometry (`pose`, `velocity`, `stalled`) and driving.
#[pyclass(frozen, module = "player3")]
pub struct Position2d {
    pub core: DeviceCore,
}

impl Position2d {
    /// The newest odometry; right after subscribing, waits for the first.
    fn odometry(&self, py: Python<'_>) -> PyResult<Position2dData> {
        let what = format!(
            "odometry of {} on {}",
            self.core.label, self.core.link.place
        );
        wait_for(
            py,
            &self.core.link.wakeup,
            FIRST_READING,
            &what,
            || self.core.newest::<Position2dData>().map(|(d, _)| d),
            || self.core.link.check_connected(),
        )
    }

    fn drive(&self, vx: f64, vy: f64, vyaw: f64, motors: bool) -> PyResult<()> {
        self.core.command(Messages::Velocity(Position2dCmdVel {
            vel: Pose2d::new(vx, vy, vyaw),
            state: u8::from(motors),
        }))
    }
}

#[pymethods]
impl Position2d {
    /// `(x, y, yaw)`: where odometry says the robot is (m, m, rad).
    #[getter]
    fn pose(&self, py: Python<'_>) -> PyResult<(f64, f64, f64)> {
        let p = self.odometry(py)?.pos;
        Ok((p.px, p.py, p.pa))
    }

    /// `(vx, vy, vyaw)`: the robot's velocity (m/s, m/s, rad/s).
    #[getter]
    fn velocity(&self, py: Python<'_>) -> PyResult<(f64, f64, f64)> {
        let v = self.odometry(py)?.vel;
        Ok((v.px, v.py, v.pa))
    }

    /// Whether the robot is pushing against something and cannot move.
    #[getter]
    fn stalled(&self, py: Python<'_>) -> PyResult<bool> {
        Ok(self.odometry(py)?.stall != 0)
    }

    /// Drives at `vx` m/s forward, `vyaw` rad/s turning (counter-clockwise), `vy` m/s sideways.
    #[pyo3(signature = (vx, vyaw, vy = 0.0))]
    fn set_velocity(&self, vx: f64, vyaw: f64, vy: f64) -> PyResult<()> {
        self.drive(vx, vy, vyaw, true)
    }

    /// Stops the robot.
    fn stop(&self) -> PyResult<()> {
        self.drive(0.0, 0.0, 0.0, true)
    }

    /// Drives to `(x, y, yaw)` in odometry coordinates. With a `timeout`, waits until the robot
    /// is within `tolerance` metres of the point (`TimeoutError` if it is not by then).
    #[pyo3(signature = (x, y, yaw, timeout = None, tolerance = 0.1))]
    fn go_to(
        &self,
        py: Python<'_>,
        x: f64,
        y: f64,
        yaw: f64,
        timeout: Option<f64>,
        tolerance: f64,
    ) -> PyResult<()> {
        self.core.command(Messages::Position(Position2dCmdPos {
            pos: Pose2d::new(x, y, yaw),
            vel: Pose2d::default(),
            state: 1,
        }))?;
        let Some(timeout) = timeout else {
            return Ok(());
        };
        let limit = timeout_arg(timeout, "go_to")?;
        let started = Instant::now();
        let what = format!("{} going to ({x}, {y})", self.core.label);
        let near = || {
            self.core
                .newest::<Position2dData>()
                .and_then(|(d, _)| ((d.pos.px - x).hypot(d.pos.py - y) <= tolerance).then_some(()))
        };
        wait_for(py, &self.core.link.wakeup, limit, &what, near, || {
            self.core.link.check_connected()
        })
        .map_err(|e| {
            if e.is_instance_of::<PyTimeoutError>(py) {
                PyTimeoutError::new_err(format!(
                    "{what}: not there after {:.1} s",
                    started.elapsed().as_secs_f64()
                ))
            } else {
                e
            }
        })
    }

    /// Turns the motors on or off (a refusal raises `RequestRefused`).
    fn enable_motors(&self, py: Python<'_>, on: bool) -> PyResult<()> {
        let power = Position2dPower {
            state: u8::from(on),
        };
        self.core
            .set(py, Messages::REQ_MOTOR_POWER, power)
            .map(|_| ())
    }

    /// `((x, y, yaw), (length, width))` of the base on the robot (m, rad).
    fn geometry(&self, py: Python<'_>) -> PyResult<crate::rangers::Placement> {
        let g = self.core.fetch(py, Messages::REQ_GET_GEOM)?;
        Ok(((g.pose.px, g.pose.py, g.pose.pyaw), (g.size.sl, g.size.sw)))
    }

    fn __repr__(&self) -> String {
        format!(
            "<Position2d {} on {}>",
            self.core.label, self.core.link.place
        )
    }
}

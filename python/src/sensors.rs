//! The small sensors and actuators: fiducial finder, blob finder, bumpers, power pack,
//! gripper. Each reading becomes a plain Python object with named fields.

use player_proto::interfaces::blobfinder::BlobfinderData;
use player_proto::interfaces::bumper::BumperData;
use player_proto::interfaces::fiducial::FiducialData;
use player_proto::interfaces::gripper::{
    Gripper as GripperMessages, GripperData, GripperSignal, STATE_CLOSED, STATE_MOVING, STATE_OPEN,
};
use player_proto::interfaces::power::PowerData;
use pyo3::prelude::*;

use crate::link::DeviceCore;
use crate::readable::readable;

/// A fiducial marker seen by a fiducial finder, in the sensor's frame (m, rad).
#[pyclass(frozen, get_all, module = "player3")]
#[derive(Clone)]
pub struct Marker {
    pub id: i32,
    pub x: f64,
    pub y: f64,
    pub yaw: f64,
}

#[pymethods]
impl Marker {
    fn __repr__(&self) -> String {
        format!(
            "Marker(id={}, x={:.3}, y={:.3}, yaw={:.3})",
            self.id, self.x, self.y, self.yaw
        )
    }
}

fn markers(data: FiducialData) -> Vec<Marker> {
    data.fiducials
        .iter()
        .map(|f| Marker {
            id: f.id,
            x: f.pose.px,
            y: f.pose.py,
            yaw: f.pose.pyaw,
        })
        .collect()
}

/// A `fiducial` finder: `read()` gives the markers in view.
#[pyclass(frozen, module = "player3")]
pub struct Fiducial {
    pub core: DeviceCore,
}
readable!(Fiducial, FiducialData, markers, Vec<Marker>, "fiducial reading" {});

/// A colour blob seen by a blob finder: image box in pixels, range in m.
#[pyclass(frozen, get_all, module = "player3")]
#[derive(Clone)]
pub struct Blob {
    pub id: u32,
    /// `0xRRGGBB`.
    pub color: u32,
    pub area: u32,
    pub x: u32,
    pub y: u32,
    pub left: u32,
    pub right: u32,
    pub top: u32,
    pub bottom: u32,
    pub range: f32,
}

#[pymethods]
impl Blob {
    fn __repr__(&self) -> String {
        format!(
            "Blob(color=0x{:06x}, x={}, y={}, area={}, range={:.2})",
            self.color, self.x, self.y, self.area, self.range
        )
    }
}

fn blobs(data: BlobfinderData) -> Vec<Blob> {
    data.blobs
        .iter()
        .map(|b| Blob {
            id: b.id,
            color: b.color,
            area: b.area,
            x: b.x,
            y: b.y,
            left: b.left,
            right: b.right,
            top: b.top,
            bottom: b.bottom,
            range: b.range,
        })
        .collect()
}

/// A `blobfinder`: `read()` gives the blobs in view.
#[pyclass(frozen, module = "player3")]
pub struct Blobfinder {
    pub core: DeviceCore,
}
readable!(Blobfinder, BlobfinderData, blobs, Vec<Blob>, "blob reading" {});

fn pressed(data: BumperData) -> Vec<bool> {
    data.bumpers.0.iter().map(|&b| b != 0).collect()
}

/// A `bumper` array: `read()` gives one `bool` per bumper, `True` when pressed.
#[pyclass(frozen, module = "player3")]
pub struct Bumper {
    pub core: DeviceCore,
}
readable!(Bumper, BumperData, pressed, Vec<bool>, "bumper reading" {});

/// A power pack's state.
#[pyclass(frozen, get_all, module = "player3")]
#[derive(Clone)]
pub struct Battery {
    pub volts: f32,
    pub percent: f32,
    pub joules: f32,
    pub watts: f32,
    pub charging: bool,
}

#[pymethods]
impl Battery {
    fn __repr__(&self) -> String {
        format!(
            "Battery(percent={:.1}, volts={:.2}, joules={:.1}, charging={})",
            self.percent, self.volts, self.joules, self.charging
        )
    }
}

fn battery(data: PowerData) -> Battery {
    Battery {
        volts: data.volts,
        percent: data.percent,
        joules: data.joules,
        watts: data.watts,
        charging: data.charging != 0,
    }
}

/// A `power` device: `read()` gives a `Battery`.
#[pyclass(frozen, module = "player3")]
pub struct Power {
    pub core: DeviceCore,
}
readable!(Power, PowerData, battery, Battery, "power reading" {});

/// A gripper's state: `state` is `"open"`, `"closed"`, `"moving"` or `"error"`.
#[pyclass(frozen, get_all, module = "player3")]
#[derive(Clone)]
pub struct GripperState {
    pub state: String,
    /// Break-beams interrupted, one bit each.
    pub beams: u32,
    /// Objects held in store.
    pub stored: u8,
}

#[pymethods]
impl GripperState {
    fn __repr__(&self) -> String {
        format!(
            "GripperState(state={:?}, beams={}, stored={})",
            self.state, self.beams, self.stored
        )
    }
}

fn gripper_state(data: GripperData) -> GripperState {
    let state = match data.state {
        STATE_OPEN => "open",
        STATE_CLOSED => "closed",
        STATE_MOVING => "moving",
        _ => "error",
    };
    GripperState {
        state: state.into(),
        beams: data.beams,
        stored: data.stored,
    }
}

/// A `gripper`: `open()`, `close()`, and its state from `read()`.
#[pyclass(frozen, module = "player3")]
pub struct Gripper {
    pub core: DeviceCore,
}
#[pymethods]
impl Gripper {
    /// Waits for the next new state; `TimeoutError` after `timeout` seconds (0: only look).
    #[pyo3(signature = (timeout = 1.0))]
    fn read(&self, py: Python<'_>, timeout: f64) -> PyResult<GripperState> {
        let limit = crate::waiting::timeout_arg(timeout, "gripper read")?;
        let (data, _) = self.core.next::<GripperData>(py, limit)?;
        Ok(gripper_state(data))
    }

    /// The newest state, or `None` before the first.
    #[getter]
    fn latest(&self) -> Option<GripperState> {
        self.core
            .newest::<GripperData>()
            .map(|(d, _)| gripper_state(d))
    }

    /// Opens the paddles.
    fn open(&self) -> PyResult<()> {
        self.core.command(GripperMessages::Open(GripperSignal {}))
    }

    /// Closes the paddles (on whatever is between them).
    fn close(&self) -> PyResult<()> {
        self.core.command(GripperMessages::Close(GripperSignal {}))
    }

    /// Stops the paddles where they are.
    fn stop(&self) -> PyResult<()> {
        self.core.command(GripperMessages::Stop(GripperSignal {}))
    }
}

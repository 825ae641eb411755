//! `robot.camera(i)`: frames as numpy `uint8` arrays, height x width x 3 (RGB), JPEG decoded.

use numpy::{PyArray1, PyArray3, PyArrayMethods};
use player_proto::interfaces::camera::CameraData;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyBytes;

use crate::link::DeviceCore;
use crate::pictures::RgbFrame;
use crate::waiting::timeout_arg;

fn decode(label: &str, frame: &CameraData) -> PyResult<RgbFrame> {
    let rgba = frame
        .to_rgba()
        .map_err(|e| PyValueError::new_err(format!("{label}: the frame does not decode: {e}")))?;
    let (width, height) = (rgba.width() as usize, rgba.height() as usize);
    let pixels = rgba
        .as_raw()
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    Ok(RgbFrame {
        width,
        height,
        pixels,
    })
}

/// The frame as a `player3.frame.Frame`: a numpy array that Jupyter shows as a picture.
fn to_array<'py>(py: Python<'py>, rgb: RgbFrame) -> PyResult<Bound<'py, PyAny>> {
    let shape = [rgb.height, rgb.width, 3];
    let array: Bound<'py, PyArray3<u8>> = PyArray1::from_vec(py, rgb.pixels).reshape(shape)?;
    let frame = py.import("player3.frame")?.getattr("Frame")?;
    array.call_method1("view", (frame,))
}

/// A `camera`: `read()` gives the next frame as an H x W x 3 `uint8` array.
#[pyclass(frozen, module = "player3")]
pub struct Camera {
    pub core: DeviceCore,
}

#[pymethods]
impl Camera {
    /// Waits for the next new frame; `TimeoutError` after `timeout` s.
    #[pyo3(signature = (timeout = 1.0))]
    fn read<'py>(&self, py: Python<'py>, timeout: f64) -> PyResult<Bound<'py, PyAny>> {
        let limit = timeout_arg(timeout, "camera read")?;
        let (frame, _) = self.core.next::<CameraData>(py, limit)?;
        let rgb = py.detach(|| decode(&self.core.label, &frame))?;
        to_array(py, rgb)
    }

    /// The newest frame, or `None` before the first.
    #[getter]
    fn latest<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        match self.core.newest::<CameraData>() {
            Some((frame, _)) => Ok(Some(to_array(py, decode(&self.core.label, &frame)?)?)),
            None => Ok(None),
        }
    }

    /// The newest frame as PNG bytes (what Jupyter shows for a camera).
    #[pyo3(signature = (timeout = None))]
    fn png<'py>(&self, py: Python<'py>, timeout: Option<f64>) -> PyResult<Bound<'py, PyBytes>> {
        let limit = timeout_arg(timeout.unwrap_or(1.0), "camera png")?;
        let (frame, _) = match self.core.newest::<CameraData>() {
            Some(found) => found,
            None => self.core.next::<CameraData>(py, limit)?,
        };
        let rgb = decode(&self.core.label, &frame)?;
        Ok(PyBytes::new(py, &crate::pictures::rgb_png(&rgb)?))
    }

    fn _repr_png_<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        self.png(py, None)
    }

    fn __repr__(&self) -> String {
        format!("<Camera {} on {}>", self.core.label, self.core.link.place)
    }
}

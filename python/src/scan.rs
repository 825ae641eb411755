//! A range scan as Python sees it: numpy arrays made straight from the decoded message
//! (one copy, no Python loop), the same for a laser, a ranger and a sonar ring.

use std::sync::OnceLock;

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyBytes;

/// Where each beam starts and points, in the robot frame: one bearing for a laser's fan, a
/// pose per transducer for a sonar ring or a multi-element ranger.
#[derive(Clone)]
pub enum Beams {
    /// Beam `i` points at `min_angle + i * resolution`, from the sensor's origin.
    Fan { min_angle: f32, resolution: f32 },
    /// `(x, y, yaw)` of each transducer.
    Poses(Vec<(f32, f32, f32)>),
}

/// One reading of a range sensor.
#[pyclass(frozen, module = "player3")]
pub struct Scan {
    ranges: Vec<f32>,
    beams: Beams,
    intensities: Vec<f32>,
    /// The server's timestamp of the reading, s.
    #[pyo3(get)]
    time: f64,
    /// The sensor's maximum range, m (readings at it saw nothing).
    #[pyo3(get)]
    max_range: f32,
    /// The numpy array of `ranges`, made on first use and shared after.
    ranges_array: OnceLock<Py<PyArray1<f32>>>,
}

impl Scan {
    pub fn new(
        ranges: Vec<f32>,
        beams: Beams,
        intensities: Vec<f32>,
        time: f64,
        max_range: f32,
    ) -> Scan {
        Scan {
            ranges,
            beams,
            intensities,
            time,
            max_range,
            ranges_array: OnceLock::new(),
        }
    }

    fn bearing_list(&self) -> Vec<f32> {
        match &self.beams {
            Beams::Fan {
                min_angle,
                resolution,
            } => (0..self.ranges.len())
                .map(|i| min_angle + i as f32 * resolution)
                .collect(),
            Beams::Poses(poses) => (0..self.ranges.len())
                .map(|i| poses.get(i).map_or(0.0, |p| p.2))
                .collect(),
        }
    }

    /// Each reading's end point in the robot frame.
    pub fn point_list(&self) -> Vec<[f32; 2]> {
        let origin = |i: usize| match &self.beams {
            Beams::Fan { .. } => (0.0, 0.0),
            Beams::Poses(poses) => poses.get(i).map_or((0.0, 0.0), |p| (p.0, p.1)),
        };
        self.ranges
            .iter()
            .zip(self.bearing_list())
            .enumerate()
            .map(|(i, (&r, b))| {
                let (x, y) = origin(i);
                [x + r * b.cos(), y + r * b.sin()]
            })
            .collect()
    }
}

#[pymethods]
impl Scan {
    /// The ranges, m: a numpy `float32` array, one per beam.
    #[getter]
    fn ranges<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f32>> {
        self.ranges_array
            .get_or_init(|| PyArray1::from_slice(py, &self.ranges).unbind())
            .bind(py)
            .clone()
    }

    /// Each beam's direction in the robot frame, rad (`float32`).
    #[getter]
    fn bearings<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f32>> {
        PyArray1::from_vec(py, self.bearing_list())
    }

    /// Reflectance per beam (`float32`; empty when the sensor sends none).
    #[getter]
    fn intensities<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f32>> {
        PyArray1::from_slice(py, &self.intensities)
    }

    /// The end points of the beams, N x 2 (`float32`, x forward and y left, m, robot frame).
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f32>>> {
        let flat: Vec<f32> = self.point_list().into_iter().flatten().collect();
        let n = flat.len() / 2;
        PyArray1::from_vec(py, flat).reshape([n, 2])
    }

    fn __len__(&self) -> usize {
        self.ranges.len()
    }

    fn __repr__(&self) -> String {
        let nearest = self.ranges.iter().copied().fold(f32::INFINITY, f32::min);
        format!(
            "<Scan of {} beams at t={:.3} s, nearest {:.2} m, max range {:.1} m>",
            self.ranges.len(),
            self.time,
            nearest,
            self.max_range
        )
    }

    /// A picture of the scan seen from above, for Jupyter.
    fn _repr_png_<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        let png = crate::pictures::scan_png(&self.point_list(), self.max_range)?;
        Ok(PyBytes::new(py, &png))
    }
}

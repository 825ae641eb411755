//! `robot.laser(i)`, `robot.ranger(i)`, `robot.sonar(i)`: range sensors whose readings come
//! to Python as a [`Scan`]. `read` waits for a reading newer than the last one it returned;
//! `latest` is the newest without waiting.

use std::time::Duration;

use player_proto::client::Stamped;
use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::laser::{Laser as LaserMessages, LaserScan};
use player_proto::interfaces::ranger::{Ranger as RangerMessages, RangerIntensities, RangerRanges};
use player_proto::interfaces::sonar::{Sonar as SonarMessages, SonarData};
use pyo3::prelude::*;

use crate::link::DeviceCore;
use crate::scan::{Beams, Scan};
use crate::waiting::timeout_arg;

/// `((x, y, yaw), (length, width))` of a device on its robot.
pub type Placement = ((f64, f64, f64), (f64, f64));

fn placement(pose: &Pose3d, length: f64, width: f64) -> Placement {
    ((pose.px, pose.py, pose.pyaw), (length, width))
}

fn laser_scan(scan: LaserScan, stamped: &Stamped) -> Scan {
    let intensities = scan.intensity.0.iter().map(|&i| f32::from(i)).collect();
    let beams = Beams::Fan {
        min_angle: scan.min_angle,
        resolution: scan.resolution,
    };
    Scan::new(
        scan.ranges,
        beams,
        intensities,
        stamped.server_time,
        scan.max_range,
    )
}

/// A `laser` device (a scanning range finder).
#[pyclass(frozen, module = "player3")]
pub struct Laser {
    pub core: DeviceCore,
}

#[pymethods]
impl Laser {
    /// Waits for the next new scan (never the same one twice); `TimeoutError` after `timeout` s.
    #[pyo3(signature = (timeout = 1.0))]
    fn read(&self, py: Python<'_>, timeout: f64) -> PyResult<Scan> {
        let limit: Duration = timeout_arg(timeout, "laser read")?;
        let (scan, stamped) = self.core.next::<LaserScan>(py, limit)?;
        Ok(laser_scan(scan, &stamped))
    }

    /// The newest scan, or `None` before the first.
    #[getter]
    fn latest(&self) -> Option<Scan> {
        let (scan, stamped) = self.core.newest::<LaserScan>()?;
        Some(laser_scan(scan, &stamped))
    }

    /// `((x, y, yaw), (length, width))`: where the laser sits on the robot.
    fn geometry(&self, py: Python<'_>) -> PyResult<Placement> {
        let g = self.core.fetch(py, LaserMessages::REQ_GET_GEOM)?;
        Ok(placement(&g.pose, g.size.sl, g.size.sw))
    }

    fn __repr__(&self) -> String {
        format!("<Laser {} on {}>", self.core.label, self.core.link.place)
    }
}

/// A `ranger` device: a laser-like fan, or several transducers each with its own pose.
#[pyclass(frozen, module = "player3")]
pub struct Ranger {
    pub core: DeviceCore,
    /// From the device's configuration and geometry, asked for once on opening.
    beams: Beams,
    max_range: f32,
}

impl Ranger {
    /// Asks the device how its beams are laid out: one pose per element when it has several,
    /// otherwise the fan its configuration describes.
    pub fn open(py: Python<'_>, core: DeviceCore) -> PyResult<Ranger> {
        let config = core.fetch(py, RangerMessages::REQ_GET_CONFIG).ok();
        let geometry = core.fetch(py, RangerMessages::REQ_GET_GEOM).ok();
        let poses: Vec<(f32, f32, f32)> = geometry
            .iter()
            .flat_map(|g| &g.element_poses)
            .map(|p| (p.px as f32, p.py as f32, p.pyaw as f32))
            .collect();
        let beams = match &config {
            Some(c) if poses.len() <= 1 => Beams::Fan {
                min_angle: c.min_angle as f32,
                resolution: c.angular_res as f32,
            },
            _ => Beams::Poses(poses),
        };
        let max_range = config.map_or(f32::INFINITY, |c| c.max_range as f32);
        Ok(Ranger {
            core,
            beams,
            max_range,
        })
    }

    fn scan(&self, ranges: RangerRanges, stamped: &Stamped) -> Scan {
        // Stage sends the intensities of a reading right after its ranges, stamped alike.
        let intensities = self
            .core
            .newest::<RangerIntensities>()
            .filter(|(_, s)| s.server_time == stamped.server_time)
            .map(|(i, _)| i.intensities.iter().map(|&v| v as f32).collect())
            .unwrap_or_default();
        let ranges = ranges.ranges.iter().map(|&r| r as f32).collect();
        Scan::new(
            ranges,
            self.beams.clone(),
            intensities,
            stamped.server_time,
            self.max_range,
        )
    }
}

#[pymethods]
impl Ranger {
    /// Waits for the next new reading; `TimeoutError` after `timeout` s.
    #[pyo3(signature = (timeout = 1.0))]
    fn read(&self, py: Python<'_>, timeout: f64) -> PyResult<Scan> {
        let limit = timeout_arg(timeout, "ranger read")?;
        let (ranges, stamped) = self.core.next::<RangerRanges>(py, limit)?;
        Ok(self.scan(ranges, &stamped))
    }

    /// The newest reading, or `None` before the first.
    #[getter]
    fn latest(&self) -> Option<Scan> {
        let (ranges, stamped) = self.core.newest::<RangerRanges>()?;
        Some(self.scan(ranges, &stamped))
    }

    /// `((x, y, yaw), (length, width))`: where the ranger sits on the robot.
    fn geometry(&self, py: Python<'_>) -> PyResult<Placement> {
        let g = self.core.fetch(py, RangerMessages::REQ_GET_GEOM)?;
        Ok(placement(&g.pose, g.size.sl, g.size.sw))
    }

    fn __repr__(&self) -> String {
        format!("<Ranger {} on {}>", self.core.label, self.core.link.place)
    }
}

/// A `sonar` ring: one range per transducer, each at its own pose on the robot.
#[pyclass(frozen, module = "player3")]
pub struct Sonar {
    pub core: DeviceCore,
    poses: Vec<(f32, f32, f32)>,
}

impl Sonar {
    pub fn open(py: Python<'_>, core: DeviceCore) -> PyResult<Sonar> {
        let poses = core
            .fetch(py, SonarMessages::REQ_GET_GEOM)
            .map(|g| {
                g.poses
                    .iter()
                    .map(|p| (p.px as f32, p.py as f32, p.pyaw as f32))
                    .collect()
            })
            .unwrap_or_default();
        Ok(Sonar { core, poses })
    }

    fn scan(&self, data: SonarData, stamped: &Stamped) -> Scan {
        let beams = Beams::Poses(self.poses.clone());
        Scan::new(
            data.ranges,
            beams,
            Vec::new(),
            stamped.server_time,
            f32::INFINITY,
        )
    }
}

#[pymethods]
impl Sonar {
    /// Waits for the next new reading; `TimeoutError` after `timeout` s.
    #[pyo3(signature = (timeout = 1.0))]
    fn read(&self, py: Python<'_>, timeout: f64) -> PyResult<Scan> {
        let limit = timeout_arg(timeout, "sonar read")?;
        let (data, stamped) = self.core.next::<SonarData>(py, limit)?;
        Ok(self.scan(data, &stamped))
    }

    /// The newest reading, or `None` before the first.
    #[getter]
    fn latest(&self) -> Option<Scan> {
        let (data, stamped) = self.core.newest::<SonarData>()?;
        Some(self.scan(data, &stamped))
    }

    /// `(x, y, yaw)` of each transducer on the robot.
    fn geometry(&self) -> Vec<(f32, f32, f32)> {
        self.poses.clone()
    }

    fn __repr__(&self) -> String {
        format!("<Sonar {} on {}>", self.core.label, self.core.link.place)
    }
}

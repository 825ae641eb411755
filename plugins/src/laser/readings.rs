//! One scan as the drawing code needs it, whatever message carried it: a laser's plain scan,
//! its scan with the pose it was taken at, its scan with a bearing per reading, or a ranger's
//! ranges (and intensities, which Stage sends in a message of their own).

use player_proto::interfaces::laser::{LaserScan, LaserScanAngle};

/// Where each reading points.
#[derive(Debug, Clone, PartialEq)]
pub enum Bearings {
    /// Reading `i` at `first + i * step`, rad.
    Even { first: f32, step: f32 },
    /// One bearing per reading, rad (`PLAYER_LASER_DATA_SCANANGLE`).
    Listed(Vec<f32>),
}

/// Ranges with their bearings, and intensities when the device sent some.
#[derive(Debug, Clone, PartialEq)]
pub struct Readings {
    /// m.
    pub ranges: Vec<f32>,
    pub bearings: Bearings,
    /// A reading at or beyond it is no return, m; 0 = unknown.
    pub max_range: f32,
    /// One per reading, in the device's units, or empty.
    pub intensities: Vec<f32>,
}

impl Readings {
    /// A `PLAYER_LASER_DATA_SCAN` (and the scan of a `SCANPOSE`).
    pub fn from_scan(scan: &LaserScan) -> Readings {
        Readings {
            ranges: scan.ranges.clone(),
            bearings: Bearings::Even {
                first: scan.min_angle,
                step: scan.resolution,
            },
            max_range: scan.max_range,
            intensities: per_reading_bytes(&scan.intensity, scan.ranges.len()),
        }
    }

    /// A `PLAYER_LASER_DATA_SCANANGLE`. Readings without a bearing are dropped.
    pub fn from_scan_angle(scan: &LaserScanAngle) -> Readings {
        let n = scan.ranges.len().min(scan.angles.len());
        Readings {
            ranges: scan.ranges[..n].to_vec(),
            bearings: Bearings::Listed(scan.angles[..n].to_vec()),
            max_range: scan.max_range,
            intensities: per_reading_bytes(&scan.intensity, n),
        }
    }

    /// Bearing of reading `i`, rad.
    pub fn bearing(&self, i: usize) -> f32 {
        match &self.bearings {
            Bearings::Even { first, step } => first + i as f32 * step,
            Bearings::Listed(angles) => angles.get(i).copied().unwrap_or(f32::NAN),
        }
    }

    /// The unit vector (cos, sin) of each reading's bearing; `None` for a bearing that is not
    /// a number. Evenly spaced bearings are turned by one rotation per reading (in `f64`, so a
    /// 1081-beam scan ends within 1e-12 rad of where it should) instead of a sine and cosine
    /// each: a frame of 256 scans computes 92 000 of them.
    pub fn directions(&self) -> impl Iterator<Item = Option<(f32, f32)>> + '_ {
        let n = self.ranges.len();
        let (mut even, listed) = match &self.bearings {
            Bearings::Even { first, step } => {
                let (s, c) = f64::from(*first).sin_cos();
                let turn = f64::from(*step).sin_cos();
                let finite = first.is_finite() && step.is_finite();
                (finite.then_some(((c, s), turn)), None)
            }
            Bearings::Listed(angles) => (None, Some(angles)),
        };
        (0..n).map(move |i| match (&mut even, listed) {
            (Some(((c, s), (ts, tc))), _) => {
                let here = (*c as f32, *s as f32);
                (*c, *s) = (*c * *tc - *s * *ts, *s * *tc + *c * *ts);
                Some(here)
            }
            (None, Some(angles)) => {
                let a = angles.get(i).copied().filter(|a| a.is_finite())?;
                let (s, c) = a.sin_cos();
                Some((c, s))
            }
            (None, None) => None,
        })
    }

    /// Sets the intensities if there is one per reading; otherwise clears them (a count that
    /// does not match belongs to another scan).
    pub fn set_intensities(&mut self, intensities: impl ExactSizeIterator<Item = f32>) {
        self.intensities.clear();
        if intensities.len() == self.ranges.len() {
            self.intensities.extend(intensities);
        }
    }
}

/// A laser's intensity bytes as one value per reading, or none if the count does not match.
fn per_reading_bytes(bytes: &[u8], readings: usize) -> Vec<f32> {
    if bytes.len() == readings {
        bytes.iter().map(|&b| f32::from(b)).collect()
    } else {
        Vec::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use player_proto::wire::Opaque;

    #[test]
    fn a_scan_reads_evenly_spaced_bearings_and_its_intensity_bytes() {
        let scan = LaserScan {
            min_angle: -1.0,
            max_angle: 1.0,
            resolution: 1.0,
            max_range: 8.0,
            ranges: vec![1.0, 2.0, 3.0],
            intensity: Opaque::from(vec![0u8, 1, 7]),
            id: 9,
        };
        let r = Readings::from_scan(&scan);
        assert_eq!(r.bearing(2), 1.0);
        assert_eq!(r.intensities, vec![0.0, 1.0, 7.0]);
        let short = LaserScan {
            intensity: Opaque::from(vec![1u8]),
            ..scan
        };
        assert!(Readings::from_scan(&short).intensities.is_empty());
    }

    #[test]
    fn turned_directions_match_the_sines_and_cosines_of_the_bearings() {
        let scan = LaserScan {
            min_angle: -2.356,
            resolution: 0.004_363_3,
            ranges: vec![1.0; 1081],
            ..LaserScan::default()
        };
        let r = Readings::from_scan(&scan);
        for (i, d) in r.directions().enumerate() {
            let (c, s) = d.unwrap();
            let a = f64::from(r.bearing(i));
            assert!((f64::from(c) - a.cos()).abs() < 1e-6, "reading {i}");
            assert!((f64::from(s) - a.sin()).abs() < 1e-6, "reading {i}");
        }
        let broken = Readings {
            bearings: Bearings::Even {
                first: f32::NAN,
                step: 0.1,
            },
            ..r
        };
        assert!(broken.directions().all(|d| d.is_none()));
    }

    #[test]
    fn a_scan_with_angles_keeps_only_readings_that_have_one() {
        let scan = LaserScanAngle {
            max_range: 4.0,
            ranges: vec![1.0, 2.0, 3.0],
            angles: vec![0.5, -0.5],
            ..LaserScanAngle::default()
        };
        let r = Readings::from_scan_angle(&scan);
        assert_eq!(r.ranges, vec![1.0, 2.0]);
        assert_eq!(r.bearing(1), -0.5);
        assert!(r.bearing(5).is_nan());
    }

    #[test]
    fn intensities_of_another_length_are_not_paired() {
        let mut r = Readings::from_scan(&LaserScan {
            ranges: vec![1.0; 4],
            ..LaserScan::default()
        });
        r.set_intensities([1.0, 2.0].into_iter());
        assert!(r.intensities.is_empty());
        r.set_intensities([1.0, 2.0, 0.5, 1.0].into_iter());
        assert_eq!(r.intensities.len(), 4);
    }
}

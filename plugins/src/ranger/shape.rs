//! How a ranger's readings are drawn. Stage 4 serves both lasers and sonar rings as `ranger`,
//! so the shape is decided from what the device reports:
//!
//! * several elements (one pose each, one reading each) — sonar-like: one cone per element;
//! * one element and many readings over an angle — laser-like: drawn exactly as the laser
//!   plugin draws a scan (points, lines, free space), through its scan geometry code;
//! * one element and one reading — a single cone (an IR or sonar range finder).

use player_proto::interfaces::ranger::RangerConfig;

use crate::laser::{Bearings, Readings, ScanStyle, scan_geometry};
use crate::sonar::cones::{ConeStyle, Transducer, cone_geometry};
use framework::scene::Geometry;

/// Widest opening a per-element configured angle may have and still be taken as the cone width;
/// beyond it the configured angles describe something else and the `coneAngle` parameter wins.
const WIDEST_CONE: f64 = std::f64::consts::PI;

/// What [`ranger_geometry`] drew.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RangerShape {
    /// One cone per element.
    Cones,
    /// A laser-like scan.
    Scan,
    /// Readings over an angle, but the angles are not known yet (no config).
    WaitingForConfig,
    /// No readings.
    Empty,
}

/// What a ranger has told so far.
#[derive(Debug, Clone, Copy, Default)]
pub struct RangerData<'a> {
    /// The newest ranges, m.
    pub ranges: &'a [f64],
    /// The newest intensities (used when there is one per range).
    pub intensities: &'a [f64],
    /// The element poses in the drawing's frame; a single element's pose is expected to be
    /// folded into the node's transform by the caller and is not applied here.
    pub elements: &'a [Transducer],
    pub config: Option<&'a RangerConfig>,
}

/// Fills `geometry` (cleared first) with the ranges drawn in the shape the device calls for.
pub fn ranger_geometry(
    data: &RangerData<'_>,
    scan_style: &ScanStyle,
    cone_style: &ConeStyle,
    geometry: &mut Geometry,
) -> RangerShape {
    let RangerData {
        ranges,
        intensities,
        elements,
        config,
    } = *data;
    geometry.clear();
    if ranges.is_empty() {
        return RangerShape::Empty;
    }
    let ranges_f32: Vec<f32> = ranges.iter().map(|&r| r as f32).collect();
    if elements.len() > 1 || ranges.len() == 1 {
        let single = [Transducer {
            origin: glam::Vec3::ZERO,
            yaw: 0.0,
        }];
        let elements = if elements.len() > 1 {
            elements
        } else {
            &single
        };
        let mut style = *cone_style;
        if let Some(c) = config {
            let width = c.max_angle - c.min_angle;
            if width > 0.0 && width <= WIDEST_CONE {
                style.width = width as f32;
            }
            if style.no_return.is_infinite() && c.max_range > 0.0 && c.max_range.is_finite() {
                style.no_return = c.max_range as f32;
            }
        }
        cone_geometry(elements, &ranges_f32, &style, geometry);
        return RangerShape::Cones;
    }
    let Some(config) = config else {
        return RangerShape::WaitingForConfig;
    };
    let mut scan = Readings {
        ranges: ranges_f32,
        bearings: Bearings::Even {
            first: config.min_angle as f32,
            step: beam_spacing(config, ranges.len()) as f32,
        },
        max_range: config.max_range as f32,
        intensities: Vec::new(),
    };
    scan.set_intensities(intensities.iter().map(|&v| v as f32));
    scan_geometry(&scan, scan_style, geometry);
    RangerShape::Scan
}

/// The angle between readings: the configured resolution, or — when a driver leaves it zero —
/// the configured field of view spread over the readings that came.
fn beam_spacing(config: &RangerConfig, readings: usize) -> f64 {
    if config.angular_res > 0.0 && config.angular_res.is_finite() {
        return config.angular_res;
    }
    let span = config.max_angle - config.min_angle;
    if readings > 1 && span.is_finite() {
        span / (readings - 1) as f64
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn laser_config() -> RangerConfig {
        RangerConfig {
            min_angle: -std::f64::consts::FRAC_PI_2,
            max_angle: std::f64::consts::FRAC_PI_2,
            angular_res: 0.0,
            max_range: 8.0,
            ..RangerConfig::default()
        }
    }

    #[test]
    fn a_zero_resolution_is_spread_over_the_field_of_view() {
        let mut g = Geometry::default();
        let data = RangerData {
            ranges: &[1.0, 1.0, 1.0],
            config: Some(&laser_config()),
            ..RangerData::default()
        };
        let shape = ranger_geometry(&data, &ScanStyle::default(), &ConeStyle::default(), &mut g);
        assert_eq!(shape, RangerShape::Scan);
        assert!((g.points[2].pos - glam::Vec3::new(0.0, 1.0, 0.0)).length() < 1e-5);
    }

    #[test]
    fn without_config_a_scan_waits_and_a_single_reading_is_a_cone() {
        let mut g = Geometry::default();
        let style = (ScanStyle::default(), ConeStyle::default());
        let two = RangerData {
            ranges: &[1.0, 2.0],
            ..RangerData::default()
        };
        let shape = ranger_geometry(&two, &style.0, &style.1, &mut g);
        assert_eq!(shape, RangerShape::WaitingForConfig);
        assert!(g.is_empty());
        let one = RangerData {
            ranges: &[1.0],
            ..RangerData::default()
        };
        let shape = ranger_geometry(&one, &style.0, &style.1, &mut g);
        assert_eq!(shape, RangerShape::Cones);
        assert!(g.fans[0].fill.is_some(), "a filled cone");
    }

    #[test]
    fn a_scan_shaped_ranger_shades_returns_by_the_intensities_that_match() {
        let mut g = Geometry::default();
        let config = laser_config();
        let mut data = RangerData {
            ranges: &[1.0, 1.0, 1.0],
            intensities: &[1.0, 0.5, 1.0],
            config: Some(&config),
            ..RangerData::default()
        };
        let styles = (ScanStyle::default(), ConeStyle::default());
        ranger_geometry(&data, &styles.0, &styles.1, &mut g);
        assert!(
            g.points[1].color.0[0] < g.points[0].color.0[0],
            "the weaker is dimmer"
        );
        data.intensities = &[1.0, 0.5];
        ranger_geometry(&data, &styles.0, &styles.1, &mut g);
        assert!(
            g.points.iter().all(|p| p.color == styles.0.color),
            "another scan's"
        );
    }
}

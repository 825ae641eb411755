//! A laser scan as geometry in the sensor's frame: returns as points and/or a polyline, and the
//! free space it saw (the "laser C-space") as a filled polygon and its outline.

use glam::Vec3;
use player_proto::interfaces::laser::LaserScan;

use crate::config::{ConfigValueError, PluginConfig};
use crate::scene::{Geometry, Rgba};

/// How to draw a scan.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScanStyle {
    pub points: bool,
    pub lines: bool,
    pub fill_cspace: bool,
    pub draw_cspace: bool,
    pub color: Rgba,
    /// Height of the drawing above the sensor origin, m (keeps it off the ground plane).
    pub height: f32,
}

impl Default for ScanStyle {
    fn default() -> Self {
        ScanStyle {
            points: true,
            lines: false,
            fill_cspace: false,
            draw_cspace: false,
            color: Rgba::rgb(255, 90, 60),
            height: 0.0,
        }
    }
}

impl ScanStyle {
    /// The style a composition asks for (`drawPoints`, `drawLines`, `fillLaserCspace`,
    /// `drawLaserCspace`, `color`), with the defaults above: the laser's and the scan-shaped
    /// ranger's parameters are the same.
    pub fn from_config(config: &PluginConfig) -> Result<ScanStyle, ConfigValueError> {
        let defaults = ScanStyle::default();
        Ok(ScanStyle {
            points: config.bool("drawPoints", defaults.points)?,
            lines: config.bool("drawLines", defaults.lines)?,
            fill_cspace: config.bool("fillLaserCspace", defaults.fill_cspace)?,
            draw_cspace: config.bool("drawLaserCspace", defaults.draw_cspace)?,
            color: config.color("color", defaults.color)?,
            height: defaults.height,
        })
    }
}

/// Endpoint of each reading in the sensor frame. A reading at or beyond `max_range` (no
/// return) is placed at `max_range`, flagged `false`.
pub fn endpoints(scan: &LaserScan) -> impl Iterator<Item = (Vec3, bool)> + '_ {
    let max = scan.max_range;
    scan.ranges.iter().enumerate().map(move |(i, &r)| {
        let hit = r.is_finite() && r > 0.0 && (max <= 0.0 || r < max);
        let r = if hit {
            r
        } else if max > 0.0 {
            max
        } else {
            0.0
        };
        let a = scan.bearing(i);
        (Vec3::new(r * a.cos(), r * a.sin(), 0.0), hit)
    })
}

/// Fills `geometry` (cleared first) with the scan drawn in `style`.
pub fn scan_geometry(scan: &LaserScan, style: &ScanStyle, geometry: &mut Geometry) {
    geometry.clear();
    let lift = Vec3::Z * style.height;
    let rim: Vec<(Vec3, bool)> = endpoints(scan).map(|(p, hit)| (p + lift, hit)).collect();
    if style.fill_cspace && rim.len() > 1 {
        let points: Vec<Vec3> = rim.iter().map(|(p, _)| *p).collect();
        geometry.fan(lift, &points, style.color.with_alpha(60));
    }
    if style.draw_cspace && rim.len() > 1 {
        let mut outline = Vec::with_capacity(rim.len() + 1);
        outline.push(lift);
        outline.extend(rim.iter().map(|(p, _)| *p));
        geometry.polygon_outline(&outline, style.color.with_alpha(160));
    }
    if style.lines {
        for pair in rim.windows(2) {
            if pair[0].1 && pair[1].1 {
                geometry.line(pair[0].0, pair[1].0, style.color);
            }
        }
    }
    if style.points {
        for (p, hit) in &rim {
            if *hit {
                geometry.point(*p, style.color);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scan(ranges: Vec<f32>) -> LaserScan {
        let n = ranges.len() as f32;
        LaserScan {
            min_angle: -std::f32::consts::FRAC_PI_2,
            max_angle: std::f32::consts::FRAC_PI_2,
            resolution: std::f32::consts::PI / (n - 1.0),
            max_range: 8.0,
            ranges,
            ..LaserScan::default()
        }
    }

    #[test]
    fn points_sit_at_range_and_bearing_and_misses_are_skipped() {
        let mut g = Geometry::default();
        scan_geometry(&scan(vec![1.0, 2.0, 8.0]), &ScanStyle::default(), &mut g);
        assert_eq!(g.points.len(), 2, "the max-range reading is no return");
        assert!((g.points[0].pos - Vec3::new(0.0, -1.0, 0.0)).length() < 1e-5);
        assert!((g.points[1].pos - Vec3::new(2.0, 0.0, 0.0)).length() < 1e-5);
    }

    #[test]
    fn cspace_fan_and_outline_cover_every_reading() {
        let mut g = Geometry::default();
        let style = ScanStyle {
            points: false,
            fill_cspace: true,
            draw_cspace: true,
            ..ScanStyle::default()
        };
        scan_geometry(&scan(vec![1.0; 181]), &style, &mut g);
        assert_eq!(
            g.triangles.len(),
            180 * 3,
            "one triangle between neighbouring readings"
        );
        assert_eq!(g.lines.len(), 182 * 2, "origin, 181 endpoints, closed");
        assert!(g.points.is_empty());
    }
}

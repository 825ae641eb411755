//! A laser scan as geometry in the sensor's frame: returns as points and/or a polyline, and the
//! free space it saw (the "laser C-space") as a filled polygon and its outline. Returns can be
//! shaded by intensity: dim for the weakest return of the scan, full colour for the strongest.

use glam::Vec3;

use super::readings::Readings;
use framework::config::{ConfigValueError, PluginConfig};
use framework::scene::{Geometry, Rgba};

/// How bright the weakest return is drawn when shading by intensity (the strongest is 1).
const DIMMEST: f32 = 0.35;

/// How to draw a scan.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScanStyle {
    pub points: bool,
    pub lines: bool,
    pub fill_cspace: bool,
    pub draw_cspace: bool,
    pub color: Rgba,
    /// Returns shaded by their intensity, when the device sends intensities that differ.
    pub shade_intensity: bool,
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
            shade_intensity: true,
            height: 0.0,
        }
    }
}

impl ScanStyle {
    /// The style a composition asks for (`drawPoints`, `drawLines`, `fillLaserCspace`,
    /// `drawLaserCspace`, `color`, `shadeIntensity`), with the defaults above: the laser's and
    /// the scan-shaped ranger's parameters are the same.
    pub fn from_config(config: &PluginConfig) -> Result<ScanStyle, ConfigValueError> {
        let defaults = ScanStyle::default();
        Ok(ScanStyle {
            points: config.bool("drawPoints", defaults.points)?,
            lines: config.bool("drawLines", defaults.lines)?,
            fill_cspace: config.bool("fillLaserCspace", defaults.fill_cspace)?,
            draw_cspace: config.bool("drawLaserCspace", defaults.draw_cspace)?,
            color: config.color("color", defaults.color)?,
            shade_intensity: config.bool("shadeIntensity", defaults.shade_intensity)?,
            height: defaults.height,
        })
    }
}

impl ScanStyle {
    /// Writes the style back as [`ScanStyle::from_config`] reads it.
    pub fn write(&self, config: &mut PluginConfig) {
        config.set_bool("drawPoints", self.points);
        config.set_bool("drawLines", self.lines);
        config.set_bool("fillLaserCspace", self.fill_cspace);
        config.set_bool("drawLaserCspace", self.draw_cspace);
        config.set_bool("shadeIntensity", self.shade_intensity);
    }

    /// The scan controls of a plugin's panel. Returns whether anything changed.
    pub fn ui(&mut self, ui: &mut egui::Ui) -> bool {
        let before = *self;
        ui.checkbox(&mut self.points, "points");
        ui.checkbox(&mut self.lines, "lines");
        ui.checkbox(&mut self.fill_cspace, "fill free space");
        ui.checkbox(&mut self.draw_cspace, "outline free space");
        ui.checkbox(&mut self.shade_intensity, "shade returns by intensity");
        before != *self
    }
}

/// Endpoint of each reading in the sensor frame. A reading at or beyond `max_range` (no
/// return) is placed at `max_range`, flagged `false`; so is one without a usable bearing.
pub fn endpoints(scan: &Readings) -> impl Iterator<Item = (Vec3, bool)> + '_ {
    let max = scan.max_range;
    scan.ranges
        .iter()
        .zip(scan.directions())
        .map(move |(&r, direction)| {
            let hit = r.is_finite() && r > 0.0 && (max <= 0.0 || r < max);
            let r = if hit {
                r
            } else if max > 0.0 {
                max
            } else {
                0.0
            };
            let Some((cos, sin)) = direction else {
                return (Vec3::ZERO, false);
            };
            (Vec3::new(r * cos, r * sin, 0.0), hit)
        })
}

/// The colour of each return: `style.color`, or — shading by intensity, with intensities that
/// differ among the returns — from dim for the weakest return to full for the strongest.
fn return_colors<'a>(
    scan: &'a Readings,
    rim: &'a [(Vec3, bool)],
    style: &ScanStyle,
) -> impl Fn(usize) -> Rgba + 'a {
    let shading = if style.shade_intensity && scan.intensities.len() == rim.len() {
        let hits = || {
            scan.intensities
                .iter()
                .zip(rim)
                .filter(|(v, (_, hit))| *hit && v.is_finite())
                .map(|(v, _)| *v)
        };
        let lo = hits().fold(f32::INFINITY, f32::min);
        let hi = hits().fold(f32::NEG_INFINITY, f32::max);
        (hi > lo).then_some((lo, hi))
    } else {
        None
    };
    let color = style.color;
    move |i| match shading {
        Some((lo, hi)) => {
            let v = scan.intensities[i];
            let k = if v.is_finite() {
                (v - lo) / (hi - lo)
            } else {
                0.0
            };
            let scale = DIMMEST + (1.0 - DIMMEST) * k.clamp(0.0, 1.0);
            let [r, g, b, a] = color.0;
            let dim = |c: u8| (f32::from(c) * scale).round() as u8;
            Rgba([dim(r), dim(g), dim(b), a])
        }
        None => color,
    }
}

/// Fills `geometry` (cleared first) with the scan drawn in `style`.
pub fn scan_geometry(scan: &Readings, style: &ScanStyle, geometry: &mut Geometry) {
    geometry.clear();
    let lift = Vec3::Z * style.height;
    let rim: Vec<(Vec3, bool)> = endpoints(scan).map(|(p, hit)| (p + lift, hit)).collect();
    if rim.len() > 1 {
        // The free space: one fan for the fill and the outline (centre, rim, back).
        let fill = style.fill_cspace.then(|| style.color.with_alpha(60));
        let outline = style.draw_cspace.then(|| style.color.with_alpha(160));
        let points: Vec<Vec3> = rim.iter().map(|(p, _)| *p).collect();
        geometry.outlined_fan(lift, points, fill, outline);
    }
    if style.lines {
        for pair in rim.windows(2) {
            if pair[0].1 && pair[1].1 {
                geometry.line(pair[0].0, pair[1].0, style.color);
            }
        }
    }
    if style.points {
        let color_of = return_colors(scan, &rim, style);
        for (i, (p, hit)) in rim.iter().enumerate() {
            if *hit {
                geometry.point(*p, color_of(i));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::laser::readings::Bearings;

    fn scan(ranges: Vec<f32>) -> Readings {
        let n = ranges.len() as f32;
        Readings {
            ranges,
            bearings: Bearings::Even {
                first: -std::f32::consts::FRAC_PI_2,
                step: std::f32::consts::PI / (n - 1.0),
            },
            max_range: 8.0,
            intensities: Vec::new(),
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
        let fan = &g.fans[0];
        assert_eq!(
            fan.fill_triangles().count(),
            180,
            "one triangle between neighbouring readings"
        );
        assert_eq!(
            fan.outline_segments().count(),
            182,
            "origin, 181 endpoints, closed"
        );
        assert!(g.points.is_empty() && g.triangles.is_empty() && g.lines.is_empty());

        let outline_only = ScanStyle {
            fill_cspace: false,
            ..style
        };
        scan_geometry(&scan(vec![1.0; 181]), &outline_only, &mut g);
        assert_eq!(g.fans[0].fill_triangles().count(), 0);
        assert_eq!(g.fans[0].outline_segments().count(), 182);
    }

    #[test]
    fn returns_are_shaded_by_intensity_when_intensities_differ() {
        let style = ScanStyle::default();
        let mut readings = scan(vec![1.0, 2.0, 3.0, 8.0]);
        readings.intensities = vec![1.0, 0.5, 0.75, 9.0]; // the last is no return
        let mut g = Geometry::default();
        scan_geometry(&readings, &style, &mut g);
        let reds: Vec<u8> = g.points.iter().map(|p| p.color.0[0]).collect();
        let middle = (255.0 * (DIMMEST + (1.0 - DIMMEST) * 0.5)).round() as u8;
        assert_eq!(reds, vec![255, (255.0 * DIMMEST).round() as u8, middle]);

        readings.intensities = vec![1.0; 4];
        scan_geometry(&readings, &style, &mut g);
        assert!(
            g.points.iter().all(|p| p.color == style.color),
            "all alike: plain"
        );

        readings.intensities = vec![1.0, 0.5, 0.75, 1.0];
        let plain = ScanStyle {
            shade_intensity: false,
            ..style
        };
        scan_geometry(&readings, &plain, &mut g);
        assert!(
            g.points.iter().all(|p| p.color == style.color),
            "shading off"
        );
    }

    #[test]
    fn a_reading_without_a_bearing_is_no_return() {
        let readings = Readings {
            ranges: vec![1.0, 1.0],
            bearings: Bearings::Listed(vec![0.0, f32::NAN]),
            max_range: 8.0,
            intensities: Vec::new(),
        };
        let mut g = Geometry::default();
        scan_geometry(&readings, &ScanStyle::default(), &mut g);
        assert_eq!(g.points.len(), 1);
    }
}

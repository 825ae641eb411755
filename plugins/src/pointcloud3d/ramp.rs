//! Height as colour: a point's z mapped onto a blue → cyan → green → yellow → red ramp over a
//! chosen range, so that the shape of a sparse reconstruction reads without lighting. Heights
//! outside the range take the end colours.

use framework::scene::Rgba;

/// The ramp's stops, evenly spaced from the bottom of the range to the top.
const STOPS: [[u8; 3]; 5] = [
    [40, 60, 220],
    [40, 200, 230],
    [60, 200, 80],
    [240, 220, 50],
    [230, 50, 40],
];

/// The heights the ramp spans, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeightRange {
    pub low: f32,
    pub high: f32,
}

impl HeightRange {
    /// The colour of a point at height `z`.
    pub fn color_of(&self, z: f32) -> Rgba {
        let span = self.high - self.low;
        let t = if span > 0.0 && z.is_finite() {
            ((z - self.low) / span).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let scaled = t * (STOPS.len() - 1) as f32;
        let below = (scaled.floor() as usize).min(STOPS.len() - 2);
        let f = scaled - below as f32;
        let mix = |i: usize| {
            let (a, b) = (f32::from(STOPS[below][i]), f32::from(STOPS[below + 1][i]));
            (a + (b - a) * f).round() as u8
        };
        Rgba::rgb(mix(0), mix(1), mix(2))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const RANGE: HeightRange = HeightRange {
        low: 0.0,
        high: 2.0,
    };

    #[test]
    fn the_ends_and_the_middle_are_the_stops() {
        let rgb = |s: [u8; 3]| Rgba::rgb(s[0], s[1], s[2]);
        assert_eq!(RANGE.color_of(0.0), rgb(STOPS[0]));
        assert_eq!(RANGE.color_of(1.0), rgb(STOPS[2]));
        assert_eq!(RANGE.color_of(2.0), rgb(STOPS[4]));
        assert_eq!(
            RANGE.color_of(-5.0),
            rgb(STOPS[0]),
            "below: the bottom colour"
        );
        assert_eq!(RANGE.color_of(9.0), rgb(STOPS[4]), "above: the top colour");
    }

    #[test]
    fn between_stops_the_colour_is_mixed() {
        // 0.25 m is an eighth of the range: halfway between the first two stops.
        let c = RANGE.color_of(0.25);
        assert_eq!(c, Rgba::rgb(40, 130, 225));
        assert_eq!(RANGE.color_of(f32::NAN), RANGE.color_of(0.0));
    }
}

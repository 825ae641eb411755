//! Regions of the floor a teacher's checks name: where a robot must go, or must not.

use serde::Serialize;

/// A region of the floor.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Zone {
    Circle {
        x: f64,
        y: f64,
        radius: f64,
    },
    Box {
        xmin: f64,
        xmax: f64,
        ymin: f64,
        ymax: f64,
    },
}

impl Zone {
    /// How far `(x, y)` is outside the zone (0 inside).
    pub fn distance(&self, x: f64, y: f64) -> f64 {
        match *self {
            Zone::Circle {
                x: cx,
                y: cy,
                radius,
            } => ((x - cx).hypot(y - cy) - radius).max(0.0),
            Zone::Box {
                xmin,
                xmax,
                ymin,
                ymax,
            } => {
                let dx = (xmin - x).max(x - xmax).max(0.0);
                let dy = (ymin - y).max(y - ymax).max(0.0);
                dx.hypot(dy)
            }
        }
    }

    pub fn contains(&self, x: f64, y: f64) -> bool {
        self.distance(x, y) == 0.0
    }

    /// The corners of the box around the zone: (xmin, ymin), (xmax, ymax).
    pub fn bounds(&self) -> ((f64, f64), (f64, f64)) {
        match *self {
            Zone::Circle { x, y, radius } => ((x - radius, y - radius), (x + radius, y + radius)),
            Zone::Box {
                xmin,
                xmax,
                ymin,
                ymax,
            } => ((xmin, ymin), (xmax, ymax)),
        }
    }
}

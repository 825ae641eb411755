//! The `graphics2d` interface (code 55): a client draws on a 2D view (CLEAR, subtype 1, has
//! no body).

use super::common::{Color, Point2d};

pub const CMD_CLEAR: u8 = 1;

xdr_struct! {
    /// `player_graphics2d_cmd_points_t`, also the polyline and multiline commands' layout.
    pub struct Graphics2dPoints {
        pub points: Vec<Point2d>,
        pub color: Color,
    }
}

xdr_struct! {
    /// `player_graphics2d_cmd_polygon_t`.
    pub struct Graphics2dPolygon {
        pub points: Vec<Point2d>,
        pub color: Color,
        pub fill_color: Color,
        /// Non-zero = filled.
        pub filled: u8,
    }
}

interface_messages! {
    /// Commands of the `graphics2d` interface.
    pub enum Graphics2d for GRAPHICS2D {
        Command 2 as CMD_POINTS => Points(Graphics2dPoints),
        Command 3 as CMD_POLYLINE => Polyline(Graphics2dPoints),
        Command 4 as CMD_POLYGON => Polygon(Graphics2dPolygon),
        Command 5 as CMD_MULTILINE => Multiline(Graphics2dPoints),
    }
}

//! The `graphics3d` interface (code 58): a client draws in 3D. CLEAR (1), PUSH (5) and POP (6)
//! have no body.

use super::common::{Color, Point3d};

pub const CMD_CLEAR: u8 = 1;
pub const CMD_PUSH: u8 = 5;
pub const CMD_POP: u8 = 6;

/// `PLAYER_DRAW_*` modes of a draw command.
pub const DRAW_POINTS: u32 = 0;
pub const DRAW_LINES: u32 = 1;
pub const DRAW_LINE_STRIP: u32 = 2;
pub const DRAW_LINE_LOOP: u32 = 3;
pub const DRAW_TRIANGLES: u32 = 4;
pub const DRAW_TRIANGLE_STRIP: u32 = 5;
pub const DRAW_TRIANGLE_FAN: u32 = 6;
pub const DRAW_QUADS: u32 = 7;
pub const DRAW_QUAD_STRIP: u32 = 8;
pub const DRAW_POLYGON: u32 = 9;

xdr_struct! {
    /// `player_graphics3d_cmd_draw_t`.
    pub struct Graphics3dDraw {
        pub draw_mode: u32,
        pub points: Vec<Point3d>,
        pub color: Color,
    }
}

xdr_struct! {
    /// `player_graphics3d_cmd_translate_t`.
    #[derive(Copy)]
    pub struct Graphics3dTranslate {
        pub x: f64,
        pub y: f64,
        pub z: f64,
    }
}

xdr_struct! {
    /// `player_graphics3d_cmd_rotate_t`: angle (rad) about the axis (x, y, z).
    #[derive(Copy)]
    pub struct Graphics3dRotate {
        pub a: f64,
        pub x: f64,
        pub y: f64,
        pub z: f64,
    }
}

interface_messages! {
    /// Commands of the `graphics3d` interface.
    pub enum Graphics3d for GRAPHICS3D {
        Command 2 as CMD_DRAW => Draw(Graphics3dDraw),
        Command 3 as CMD_TRANSLATE => Translate(Graphics3dTranslate),
        Command 4 as CMD_ROTATE => Rotate(Graphics3dRotate),
    }
}

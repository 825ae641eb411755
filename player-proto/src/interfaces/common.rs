//! Structures shared by many interfaces (`player.h`): poses, points, boxes, colours.

xdr_struct! {
    /// `player_point_2d_t`: metres.
    #[derive(Copy)]
    pub struct Point2d {
        pub px: f64,
        pub py: f64,
    }
}

xdr_struct! {
    /// `player_point_3d_t`: metres.
    #[derive(Copy)]
    pub struct Point3d {
        pub px: f64,
        pub py: f64,
        pub pz: f64,
    }
}

xdr_struct! {
    /// `player_orientation_3d_t`: radians.
    #[derive(Copy)]
    pub struct Orientation3d {
        pub proll: f64,
        pub ppitch: f64,
        pub pyaw: f64,
    }
}

xdr_struct! {
    /// `player_pose2d_t`: x, y in metres and yaw in radians (or their rates, for velocities).
    #[derive(Copy)]
    pub struct Pose2d {
        pub px: f64,
        pub py: f64,
        pub pa: f64,
    }
}

xdr_struct! {
    /// `player_pose3d_t`: position in metres, roll/pitch/yaw in radians.
    #[derive(Copy)]
    pub struct Pose3d {
        pub px: f64,
        pub py: f64,
        pub pz: f64,
        pub proll: f64,
        pub ppitch: f64,
        pub pyaw: f64,
    }
}

xdr_struct! {
    /// `player_bbox2d_t`: width and length, metres.
    #[derive(Copy)]
    pub struct BBox2d {
        pub sw: f64,
        pub sl: f64,
    }
}

xdr_struct! {
    /// `player_bbox3d_t`: width, length and height, metres.
    #[derive(Copy)]
    pub struct BBox3d {
        pub sw: f64,
        pub sl: f64,
        pub sh: f64,
    }
}

xdr_struct! {
    /// `player_segment_t`: a line segment, metres.
    #[derive(Copy)]
    pub struct Segment {
        pub x0: f64,
        pub y0: f64,
        pub x1: f64,
        pub y1: f64,
    }
}

xdr_struct! {
    /// `player_extent2d_t`: an axis-aligned rectangle, metres (x0 < x1, y0 < y1).
    #[derive(Copy)]
    pub struct Extent2d {
        pub x0: f64,
        pub y0: f64,
        pub x1: f64,
        pub y1: f64,
    }
}

xdr_struct! {
    /// `player_color_t`: four widened bytes, 16 on the wire, alpha first.
    #[derive(Copy)]
    pub struct Color {
        pub alpha: u8,
        pub red: u8,
        pub green: u8,
        pub blue: u8,
    }
}

xdr_struct! {
    /// `player_bool_t`: a widened byte, 0 = false.
    #[derive(Copy)]
    pub struct BoolValue {
        pub state: u8,
    }
}

xdr_struct! {
    /// `player_uint32_t`.
    #[derive(Copy)]
    pub struct U32Value {
        pub value: u32,
    }
}

impl Pose2d {
    pub const fn new(px: f64, py: f64, pa: f64) -> Self {
        Self { px, py, pa }
    }
}

impl BoolValue {
    pub fn new(on: bool) -> Self {
        Self {
            state: u8::from(on),
        }
    }

    pub fn is_on(&self) -> bool {
        self.state != 0
    }
}

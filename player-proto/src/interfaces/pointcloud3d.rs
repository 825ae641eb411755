//! The `pointcloud3d` interface (code 61): coloured 3-D points, e.g. from a depth camera or a
//! tilting laser. Each point carries a full 16-byte colour, so a cloud costs 40 bytes a point
//! on the wire.

use super::common::{Color, Point3d};

xdr_struct! {
    /// `player_pointcloud3d_element_t`.
    #[derive(Copy)]
    pub struct PointCloud3dElement {
        /// m, in the sensor's frame.
        pub point: Point3d,
        pub color: Color,
    }
}

xdr_struct! {
    /// `player_pointcloud3d_data_t`.
    pub struct PointCloud3dData {
        pub points: Vec<PointCloud3dElement>,
    }
}

interface_messages! {
    /// Messages of the `pointcloud3d` interface.
    pub enum Pointcloud3d for POINTCLOUD3D {
        Data 1 as DATA_STATE => State(PointCloud3dData),
    }
}

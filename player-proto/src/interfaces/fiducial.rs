//! The `fiducial` interface (code 10): detected markers with ids and poses.

use super::common::{BBox2d, BBox3d, Pose3d};

/// Request subtypes whose request body is empty.
pub const REQ_GET_GEOM: u8 = 1;
pub const REQ_GET_FOV: u8 = 2;
pub const REQ_GET_ID: u8 = 7;

xdr_struct! {
    /// `player_fiducial_item_t`: one detected marker.
    #[derive(Copy)]
    pub struct FiducialItem {
        /// Marker id; -1 if it cannot be identified (Stage reports 0 beyond its id range).
        pub id: i32,
        /// Pose relative to the detector, m and rad.
        pub pose: Pose3d,
        /// Uncertainty of `pose`. Stage leaves it uninitialised: treat as meaningless.
        pub upose: Pose3d,
    }
}

xdr_struct! {
    /// `player_fiducial_data_t`.
    pub struct FiducialData {
        pub fiducials: Vec<FiducialItem>,
    }
}

xdr_struct! {
    /// `player_fiducial_geom_t`: detector pose and size, and the markers' size.
    #[derive(Copy)]
    pub struct FiducialGeometry {
        pub pose: Pose3d,
        pub size: BBox3d,
        pub fiducial_size: BBox2d,
    }
}

xdr_struct! {
    /// `player_fiducial_fov_t`.
    #[derive(Copy)]
    pub struct FiducialFov {
        pub min_range: f32,
        pub max_range: f32,
        pub view_angle: f32,
    }
}

xdr_struct! {
    /// `player_fiducial_id_t`.
    #[derive(Copy)]
    pub struct FiducialId {
        pub id: u32,
    }
}

interface_messages! {
    /// Messages of the `fiducial` interface (request subtypes 4–6 are unused by Player).
    pub enum Fiducial for FIDUCIAL {
        Data 1 as DATA_SCAN => Scan(FiducialData),
        Request 1 as REQ_GET_GEOM => Geometry(FiducialGeometry),
        Request 2 as REQ_GET_FOV => Fov(FiducialFov),
        Request 3 as REQ_SET_FOV => SetFov(FiducialFov),
        Request 7 as REQ_GET_ID => Id(FiducialId),
        Request 8 as REQ_SET_ID => SetId(FiducialId),
    }
}

impl FiducialItem {
    /// Distance to the marker in the detector's plane, m.
    pub fn range(&self) -> f64 {
        self.pose.px.hypot(self.pose.py)
    }

    /// Bearing of the marker from the detector, rad.
    pub fn bearing(&self) -> f64 {
        self.pose.py.atan2(self.pose.px)
    }
}

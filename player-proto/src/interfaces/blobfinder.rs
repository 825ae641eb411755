//! The `blobfinder` interface (code 7): colour blobs found in a camera image.

xdr_struct! {
    /// `player_blobfinder_blob_t`.
    #[derive(Copy)]
    pub struct Blob {
        pub id: u32,
        /// Packed 0x00RRGGBB.
        pub color: u32,
        /// Pixels.
        pub area: u32,
        pub x: u32,
        pub y: u32,
        pub left: u32,
        pub right: u32,
        pub top: u32,
        pub bottom: u32,
        /// m.
        pub range: f32,
    }
}

xdr_struct! {
    /// `player_blobfinder_data_t`.
    pub struct BlobfinderData {
        pub width: u32,
        pub height: u32,
        pub blobs: Vec<Blob>,
    }
}

xdr_struct! {
    /// `player_blobfinder_color_config_t`.
    #[derive(Copy)]
    pub struct BlobfinderColor {
        pub channel: u32,
        pub rmin: u32,
        pub rmax: u32,
        pub gmin: u32,
        pub gmax: u32,
        pub bmin: u32,
        pub bmax: u32,
    }
}

xdr_struct! {
    /// `player_blobfinder_imager_config_t`: -1 leaves a setting unchanged.
    #[derive(Copy)]
    pub struct BlobfinderImager {
        pub brightness: i32,
        pub contrast: i32,
        pub colormode: i32,
        pub autogain: i32,
    }
}

interface_messages! {
    /// Messages of the `blobfinder` interface.
    pub enum Blobfinder for BLOBFINDER {
        Data 1 as DATA_BLOBS => Blobs(BlobfinderData),
        Request 1 as REQ_SET_COLOR => SetColor(BlobfinderColor),
        Request 2 as REQ_SET_IMAGER_PARAMS => SetImagerParams(BlobfinderImager),
        Request 3 as REQ_GET_COLOR => Color(BlobfinderColor),
    }
}

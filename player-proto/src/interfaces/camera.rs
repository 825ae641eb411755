//! The `camera` interface (code 40): raw frames or JPEG files. Pixels stay a zero-copy slice of
//! the received buffer; [`CameraData::to_rgba`] decodes them when someone wants to look.

use crate::wire::{Opaque, PlayerString};

pub const FORMAT_MONO8: u32 = 1;
pub const FORMAT_MONO16: u32 = 2;
pub const FORMAT_RGB565: u32 = 4;
pub const FORMAT_RGB888: u32 = 5;
pub const COMPRESS_RAW: u32 = 0;
pub const COMPRESS_JPEG: u32 = 1;

/// Request subtypes whose request body is empty.
pub const REQ_GET_SOURCE: u8 = 1;
pub const REQ_GET_IMAGE: u8 = 3;

xdr_struct! {
    /// `player_camera_data_t`: one frame.
    pub struct CameraData {
        pub width: u32,
        pub height: u32,
        /// Bits per pixel: 8, 16, 24 or 32.
        pub bpp: u32,
        /// One of the `FORMAT_*` constants.
        pub format: u32,
        /// Scale divisor for scaled pixel values; ≤ 1 means none.
        pub fdiv: u32,
        /// `COMPRESS_RAW` or `COMPRESS_JPEG`.
        pub compression: u32,
        /// Raw pixels row-major, or a complete JPEG file.
        pub image: Opaque,
    }
}

xdr_struct! {
    /// `player_camera_source_t`: video norm and input channel.
    pub struct CameraSource {
        pub norm: PlayerString,
        pub source: i32,
    }
}

interface_messages! {
    /// Messages of the `camera` interface.
    pub enum Camera for CAMERA {
        Data 1 as DATA_STATE => State(CameraData),
        Request 1 as REQ_GET_SOURCE => Source(CameraSource),
        Request 2 as REQ_SET_SOURCE => SetSource(CameraSource),
        Request 3 as REQ_GET_IMAGE => Image(CameraData),
    }
}

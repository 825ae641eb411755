//! Camera frames with arbitrary headers and pixels: decoding to RGBA fails cleanly or succeeds.
#![no_main]

use libfuzzer_sys::fuzz_target;
use player_proto::interfaces::camera::CameraData;
use player_proto::wire::Opaque;

fuzz_target!(|data: &[u8]| {
    if data.len() < 8 {
        return;
    }
    let frame = CameraData {
        width: u32::from(u16::from_be_bytes([data[0], data[1]])),
        height: u32::from(u16::from_be_bytes([data[2], data[3]])),
        bpp: u32::from(data[4]),
        format: u32::from(data[5] % 8),
        fdiv: 1,
        compression: u32::from(data[6] % 3),
        image: Opaque::from(data[8..].to_vec()),
    };
    if let Ok(image) = frame.to_rgba() {
        assert_eq!((image.width(), image.height()), (frame.width, frame.height));
    }
});

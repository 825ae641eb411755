//! Map tiles: an arbitrary width, height and zlib stream inflate to exactly width × height
//! cells or fail cleanly, never allocating more than the claimed tile.
#![no_main]

use libfuzzer_sys::fuzz_target;
use player_proto::interfaces::map::MapData;
use player_proto::wire::Opaque;

fuzz_target!(|data: &[u8]| {
    if data.len() < 4 {
        return;
    }
    let tile = MapData {
        width: u32::from(u16::from_be_bytes([data[0], data[1]])),
        height: u32::from(u16::from_be_bytes([data[2], data[3]])),
        data: Opaque::from(data[4..].to_vec()),
        ..MapData::default()
    };
    if let Ok(cells) = tile.cells() {
        assert_eq!(
            cells.len() as u64,
            u64::from(tile.width) * u64::from(tile.height)
        );
    }
});

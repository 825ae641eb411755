//! The `map` interface (code 42): occupancy grids in tiles, and vector maps.
//!
//! On the TCP link a tile's cells travel zlib-compressed (the server compresses GET_DATA
//! ACKs); [`MapData::cells`] inflates them, never to more than the tile's width × height.

use std::io::Read;

use bytes::{BufMut, Bytes};
use nom::number::complete::be_u32;

use super::common::{Pose2d, Segment};
use crate::wire::xdr::{
    Xdr, XdrFault, XdrResult, decode_packed_bytes, encode_packed_bytes, fail, pad4,
};
use crate::wire::xdr_view::view_packed_bytes;
use crate::wire::{Opaque, XdrView};

pub const REQ_GET_INFO: u8 = 1;
pub const REQ_GET_DATA: u8 = 2;
pub const REQ_GET_VECTOR: u8 = 3;

xdr_struct! {
    /// `player_map_info_t`.
    #[derive(Copy)]
    pub struct MapInfo {
        /// m per cell.
        pub scale: f32,
        pub width: u32,
        pub height: u32,
        /// Real-world pose of cell (0, 0).
        pub origin: Pose2d,
    }
}

/// The widest and tallest tile a client asks for, cells: the cap Player's own client library
/// puts on a tile, which every `mapfile` server answers.
pub const TILE_SIDE: u32 = 640;

/// The most cells a map may have: 64 MB of cells, a 8192 × 8192 grid — a 400 m building at
/// 5 cm. A larger claim is refused before anything is allocated.
pub const MAX_MAP_CELLS: u64 = 8192 * 8192;

impl MapInfo {
    /// The GET_DATA requests (tiles without cells) that cover the map, row by row, each at
    /// most [`TILE_SIDE`] on a side; none for a map above [`MAX_MAP_CELLS`], whose claim
    /// nobody should believe.
    pub fn tile_requests(&self) -> Vec<MapData> {
        let (w, h) = (self.width, self.height);
        let mut tiles = Vec::new();
        if u64::from(w) * u64::from(h) > MAX_MAP_CELLS {
            return tiles;
        }
        for row in (0..h).step_by(TILE_SIDE as usize) {
            for col in (0..w).step_by(TILE_SIDE as usize) {
                tiles.push(MapData {
                    col,
                    row,
                    width: TILE_SIDE.min(w - col),
                    height: TILE_SIDE.min(h - row),
                    ..MapData::default()
                });
            }
        }
        tiles
    }
}

/// `player_map_data_t`: a tile. Its count, range and bytes are not adjacent (`data_count`,
/// `data_range`, then the bytes with their own length), so it has its own codec.
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(any(test, feature = "proptest"), derive(proptest_derive::Arbitrary))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MapData {
    pub col: u32,
    pub row: u32,
    pub width: u32,
    pub height: u32,
    /// Largest magnitude of a cell value.
    pub data_range: i8,
    /// Cell bytes as they travel: a zlib stream on TCP links.
    pub data: Opaque,
}

impl Xdr for MapData {
    const MIN_WIRE_SIZE: usize = 28;

    fn decode<'a>(input: &'a [u8], body: &Bytes) -> XdrResult<'a, Self> {
        let (input, col) = be_u32(input)?;
        let (input, row) = be_u32(input)?;
        let (input, width) = be_u32(input)?;
        let (input, height) = be_u32(input)?;
        let (input, count) = be_u32(input)?;
        let (input, data_range) = i8::decode(input, body)?;
        let (rest, length) = be_u32(input)?;
        if length > count {
            return fail(input, XdrFault::LengthAboveCount { count, length });
        }
        let (rest, data) = decode_packed_bytes(input, rest, length as usize, body)?;
        Ok((
            rest,
            MapData {
                col,
                row,
                width,
                height,
                data_range,
                data: Opaque(data),
            },
        ))
    }

    fn encode<B: BufMut>(&self, out: &mut B) {
        for v in [self.col, self.row, self.width, self.height] {
            out.put_u32(v);
        }
        out.put_u32(u32::try_from(self.data.len()).expect("tile above 4 GiB"));
        self.data_range.encode(out);
        encode_packed_bytes(&self.data, out);
    }

    fn encoded_len(&self) -> usize {
        28 + self.data.len() + pad4(self.data.len())
    }
}

/// [`MapData`] read in place: the tile's cells stay in the received body.
#[derive(Debug, Clone, Copy)]
pub struct MapDataView<'a> {
    pub col: u32,
    pub row: u32,
    pub width: u32,
    pub height: u32,
    pub data_range: i8,
    pub data: &'a [u8],
}

impl XdrView for MapData {
    type View<'a> = MapDataView<'a>;
    const FIXED_SIZE: Option<usize> = None;

    // The same checks, in the same order, as `decode` above.
    fn view(input: &[u8]) -> XdrResult<'_, MapDataView<'_>> {
        let (input, col) = u32::view(input)?;
        let (input, row) = u32::view(input)?;
        let (input, width) = u32::view(input)?;
        let (input, height) = u32::view(input)?;
        let (input, count) = u32::view(input)?;
        let (input, data_range) = i8::view(input)?;
        let (rest, length) = u32::view(input)?;
        if length > count {
            return fail(input, XdrFault::LengthAboveCount { count, length });
        }
        let (rest, data) = view_packed_bytes(input, rest, length as usize)?;
        Ok((
            rest,
            MapDataView {
                col,
                row,
                width,
                height,
                data_range,
                data,
            },
        ))
    }

    fn to_owned_value(view: MapDataView<'_>) -> MapData {
        MapData {
            col: view.col,
            row: view.row,
            width: view.width,
            height: view.height,
            data_range: view.data_range,
            data: Opaque(Bytes::copy_from_slice(view.data)),
        }
    }
}

/// The most cells a tile may inflate to: Player's hard message limit
/// (`PLAYERXDR_MAX_MESSAGE_SIZE`, 32 MiB), far above any real tile. Without it a lying width ×
/// height plus a small zlib bomb could make [`MapData::cells`] allocate gigabytes.
pub const MAX_TILE_CELLS: usize = 32 * 1024 * 1024;

/// Why a tile's cells cannot be had.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MapError {
    #[error("a {width}×{height} tile exceeds the {MAX_TILE_CELLS}-cell limit")]
    TileTooLarge { width: u32, height: u32 },
    #[error("tile data is not a zlib stream: {0}")]
    Inflate(String),
    #[error("tile inflates to more than its {expected} cells")]
    TooLarge { expected: usize },
    #[error("tile inflates to {actual} cells, its size says {expected}")]
    Short { expected: usize, actual: usize },
}

impl MapData {
    /// Compresses `cells` (row-major, width × height) into a tile, as a server sends it.
    pub fn compress(
        col: u32,
        row: u32,
        width: u32,
        height: u32,
        data_range: i8,
        cells: &[i8],
    ) -> MapData {
        use flate2::Compression;
        use flate2::write::ZlibEncoder;
        use std::io::Write;
        let raw: Vec<u8> = cells.iter().map(|&c| c as u8).collect();
        let mut encoder = ZlibEncoder::new(Vec::new(), Compression::default());
        encoder.write_all(&raw).expect("writing to memory");
        MapData {
            col,
            row,
            width,
            height,
            data_range,
            data: Opaque::from(encoder.finish().expect("writing to memory")),
        }
    }

    /// The cells, inflated: negative free, 0 unknown, positive occupied.
    pub fn cells(&self) -> Result<Vec<i8>, MapError> {
        let expected = u64::from(self.width) * u64::from(self.height);
        if expected > MAX_TILE_CELLS as u64 {
            return Err(MapError::TileTooLarge {
                width: self.width,
                height: self.height,
            });
        }
        let expected = expected as usize;
        let mut out = Vec::with_capacity(expected.min(self.data.len() * 1032 + 64));
        flate2::read::ZlibDecoder::new(&self.data[..])
            .take(expected as u64 + 1)
            .read_to_end(&mut out)
            .map_err(|e| MapError::Inflate(e.to_string()))?;
        if out.len() > expected {
            return Err(MapError::TooLarge { expected });
        }
        if out.len() < expected {
            return Err(MapError::Short {
                expected,
                actual: out.len(),
            });
        }
        Ok(out.into_iter().map(|b| b as i8).collect())
    }
}

xdr_struct! {
    /// `player_map_data_vector_t`: line segments and their bounding box.
    pub struct MapVector {
        pub minx: f32,
        pub maxx: f32,
        pub miny: f32,
        pub maxy: f32,
        pub segments: Vec<Segment>,
    }
}

interface_messages! {
    /// Messages of the `map` interface.
    pub enum Map for MAP {
        Data 1 as DATA_INFO => InfoData(MapInfo),
        Request 1 as REQ_GET_INFO => Info(MapInfo),
        Request 2 as REQ_GET_DATA => Tile(MapData),
        Request 3 as REQ_GET_VECTOR => Vector(MapVector),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wire::xdr::decode_all;

    #[test]
    fn tiles_travel_compressed_with_count_range_length_order() {
        let cells: Vec<i8> = (0..64).map(|i| if i % 3 == 0 { 1 } else { -1 }).collect();
        let tile = MapData::compress(0, 0, 8, 8, 1, &cells);
        let mut wire = Vec::new();
        tile.encode(&mut wire);
        assert_eq!(wire.len(), tile.encoded_len());
        // count, then the range in its own 4-byte slot, then the length again.
        assert_eq!(&wire[16..20], &(tile.data.len() as u32).to_be_bytes());
        assert_eq!(&wire[20..24], &[0, 0, 0, 1]);
        assert_eq!(&wire[24..28], &(tile.data.len() as u32).to_be_bytes());
        let body = Bytes::from(wire);
        let (back, trailing) = decode_all::<MapData>(&body).unwrap();
        assert_eq!((back.clone(), trailing), (tile, 0));
        assert_eq!(back.cells().unwrap(), cells);
    }

    #[test]
    fn a_zip_bomb_is_refused() {
        let huge = vec![0i8; 1 << 20];
        let mut bomb = MapData::compress(0, 0, 1 << 10, 1 << 10, 1, &huge);
        bomb.width = 16;
        bomb.height = 16;
        assert_eq!(bomb.cells(), Err(MapError::TooLarge { expected: 256 }));
        let garbage = MapData {
            width: 2,
            height: 2,
            data: Opaque::from(vec![1, 2, 3]),
            ..MapData::default()
        };
        assert!(matches!(garbage.cells(), Err(MapError::Inflate(_))));
        let lying = MapData {
            width: 65536,
            height: 65536,
            ..tile_of(&[0; 4])
        };
        assert_eq!(
            lying.cells(),
            Err(MapError::TileTooLarge {
                width: 65536,
                height: 65536
            })
        );
    }

    fn tile_of(cells: &[i8]) -> MapData {
        MapData::compress(0, 0, 2, 2, 1, cells)
    }
}

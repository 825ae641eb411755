//! The lengths an MCAP record's body declares for its strings, maps and byte arrays, checked
//! against the bytes the body has before the `mcap` crate parses it: that parser reserves
//! whatever a length field claims (up to 4 GiB for a string) before it finds the bytes are not
//! there, so one damaged length in a 100-byte record asked for gigabytes. Each record's fields
//! are a table below (the MCAP specification's record layouts: facts, not code); one walk reads
//! any of them.

/// A field of a record, in the order the record holds them.
#[derive(Clone, Copy)]
enum Field {
    /// Fixed-size: so many bytes.
    Fixed(usize),
    /// A `u32` byte length, then UTF-8 bytes.
    Str,
    /// A `u32` byte length, then that many bytes.
    Bytes32,
    /// A `u64` byte length, then that many bytes.
    Bytes64,
    /// A `u32` byte length, then string keys and string values, pair by pair.
    StrMap,
    /// A `u32` byte length, then entries of so many bytes each: whole entries only, since the
    /// parser reads a whole entry whenever any of the length is left.
    FixedMap(usize),
    /// Whatever remains (a message's data).
    Rest,
}

use Field::{Bytes32, Bytes64, Fixed, FixedMap, Rest, Str, StrMap};

/// An entry of a map from channel id to count or offset (`u16`, `u64`).
const CHANNEL_ENTRY: usize = 2 + 8;
/// A message index entry: log time and offset (`u64`, `u64`).
const INDEX_ENTRY: usize = 8 + 8;

/// Each record kind's name and fields, by opcode; `None` for an opcode MCAP does not define
/// (the reader passes over those).
fn layout(opcode: u8) -> Option<(&'static str, &'static [Field])> {
    Some(match opcode {
        0x01 => ("header", &[Str, Str]),
        0x02 => ("footer", &[Fixed(8), Fixed(8), Fixed(4)]),
        0x03 => ("schema", &[Fixed(2), Str, Str, Bytes32]),
        0x04 => ("channel", &[Fixed(2), Fixed(2), Str, Str, StrMap]),
        0x05 => ("message", &[Fixed(2), Fixed(4), Fixed(8), Fixed(8), Rest]),
        0x06 => (
            "chunk",
            &[Fixed(8), Fixed(8), Fixed(8), Fixed(4), Str, Bytes64],
        ),
        0x07 => ("message index", &[Fixed(2), FixedMap(INDEX_ENTRY)]),
        0x08 => (
            "chunk index",
            &[Fixed(32), FixedMap(CHANNEL_ENTRY), Fixed(8), Str, Fixed(16)],
        ),
        0x09 => ("attachment", &[Fixed(16), Str, Str, Bytes64, Fixed(4)]),
        0x0A => ("attachment index", &[Fixed(40), Str, Str]),
        0x0B => ("statistics", &[Fixed(42), FixedMap(CHANNEL_ENTRY)]),
        0x0C => ("metadata", &[Str, StrMap]),
        0x0D => ("metadata index", &[Fixed(16), Str]),
        0x0E => ("summary offset", &[Fixed(17)]),
        0x0F => ("data end", &[Fixed(4)]),
        _ => return None,
    })
}

/// Is `opcode` a record a summary section holds (schemas, channels, the indexes, statistics,
/// summary offsets)? A chunk or a message there is damage: the summary reader would open it
/// and parse what it holds unchecked.
pub fn in_summary(opcode: u8) -> bool {
    matches!(opcode, 0x03 | 0x04 | 0x08 | 0x0A | 0x0B | 0x0D | 0x0E)
}

/// A length a record declares past the end of its body.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "the {record} record's field {field} claims {claimed} bytes, but only {left} remain in the record"
)]
pub struct LengthPastRecord {
    pub record: &'static str,
    /// Which field, counted from 1 (within a map, the map's).
    pub field: usize,
    pub claimed: u64,
    pub left: usize,
}

/// Checks that every length record `opcode`'s body `body` declares fits within it (a record of
/// an opcode MCAP does not define passes: nothing in it is parsed).
pub fn check(opcode: u8, body: &[u8]) -> Result<(), LengthPastRecord> {
    let Some((record, fields)) = layout(opcode) else {
        return Ok(());
    };
    let mut rest = body;
    for (k, &field) in fields.iter().enumerate() {
        let fault = |claimed: u64, left: usize| LengthPastRecord {
            record,
            field: k + 1,
            claimed,
            left,
        };
        let (claimed, prefix) = match field {
            Fixed(n) => (n as u64, 0),
            Str | Bytes32 | StrMap | FixedMap(_) => (word(rest, 4).ok_or(fault(4, rest.len()))?, 4),
            Bytes64 => (word(rest, 8).ok_or(fault(8, rest.len()))?, 8),
            Rest => return Ok(()),
        };
        let left = rest.len() - prefix;
        let partial = matches!(field, FixedMap(entry) if claimed % entry as u64 != 0);
        if claimed > left as u64 || partial {
            return Err(fault(claimed, left));
        }
        let (inside, after) = rest[prefix..].split_at(claimed as usize);
        if let StrMap = field {
            // A key and its value, each a string of its own, both within the map's bytes: the
            // parser reads a value after every key however little of the map is left.
            let mut entries = inside;
            while !entries.is_empty() {
                for _ in ["key", "value"] {
                    let n = word(entries, 4).ok_or(fault(4, entries.len()))?;
                    if n > (entries.len() - 4) as u64 {
                        return Err(fault(n, entries.len() - 4));
                    }
                    entries = &entries[4 + n as usize..];
                }
            }
        }
        rest = after;
    }
    Ok(())
}

/// The little-endian number of `width` bytes at the start of `bytes`, if they are there.
fn word(bytes: &[u8], width: usize) -> Option<u64> {
    let mut v = [0u8; 8];
    v[..width].copy_from_slice(bytes.get(..width)?);
    Some(u64::from_le_bytes(v))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A string field as MCAP writes it.
    fn string(s: &str) -> Vec<u8> {
        let mut v = (s.len() as u32).to_le_bytes().to_vec();
        v.extend_from_slice(s.as_bytes());
        v
    }

    fn channel(topic_length: u32) -> Vec<u8> {
        let mut body = vec![1, 0, 0, 0];
        body.extend(topic_length.to_le_bytes());
        body.extend(b"/r0/laser");
        body.extend(string("player-xdr"));
        let map = [string("player.connection"), string("1")].concat();
        body.extend((map.len() as u32).to_le_bytes());
        body.extend(map);
        body
    }

    #[test]
    fn a_whole_record_passes_and_a_length_past_its_end_is_named() {
        assert_eq!(check(0x04, &channel(9)), Ok(()));
        let err = check(0x04, &channel(3_327_152_921)).unwrap_err();
        assert_eq!(
            (err.record, err.field, err.claimed),
            ("channel", 3, 3_327_152_921)
        );
        assert!(
            err.to_string()
                .contains("channel record's field 3 claims 3327152921 bytes")
        );
    }

    #[test]
    fn a_map_entry_past_its_map_is_refused() {
        let mut body = channel(9);
        // The map's first key claims more than the map holds.
        let at = body.len() - string("player.connection").len() - string("1").len();
        body[at..at + 4].copy_from_slice(&1000u32.to_le_bytes());
        assert_eq!(check(0x04, &body).unwrap_err().claimed, 1000);
    }

    #[test]
    fn a_map_holding_a_key_without_its_value_is_refused() {
        // The fuzzer's case: the map's four bytes hold an empty key, and the bytes after the
        // map would be read as its value's length (2.4 GB).
        let mut body = string("player.r\0\0\0\0");
        body.extend(4u32.to_le_bytes());
        body.extend(string(""));
        body.extend(0x919b_7961u32.to_le_bytes());
        let err = check(0x0C, &body).unwrap_err();
        assert_eq!((err.record, err.field, err.claimed), ("metadata", 2, 4));
    }

    #[test]
    fn a_map_of_part_of_an_entry_is_refused() {
        // A chunk index whose offsets map claims 47 bytes: the parser reads five whole
        // 10-byte entries, three bytes past it, and its compression's length from there.
        let mut body = vec![0u8; 32];
        body.extend(47u32.to_le_bytes());
        body.extend([0u8; 47 + 8 + 4 + 16]);
        let err = check(0x08, &body).unwrap_err();
        assert_eq!((err.record, err.field, err.claimed), ("chunk index", 2, 47));
        body[32..36].copy_from_slice(&40u32.to_le_bytes());
        body.truncate(32 + 4 + 40 + 8 + 4 + 16);
        assert_eq!(check(0x08, &body), Ok(()));
    }

    #[test]
    fn a_record_cut_inside_a_fixed_field_or_a_length_is_refused() {
        let body = channel(9);
        for cut in [1, 5, 7] {
            assert!(check(0x04, &body[..cut]).is_err(), "cut at {cut}");
        }
        assert!(check(0x02, &[0; 19]).is_err());
        assert_eq!(check(0x02, &[0; 20]), Ok(()));
        // A message's data is whatever follows its header.
        assert_eq!(check(0x05, &[0; 22]), Ok(()));
        assert!(check(0x05, &[0; 21]).is_err());
        // Opcodes MCAP leaves free pass: nothing of them is read.
        assert_eq!(check(0x80, &[0xff; 3]), Ok(()));
    }
}

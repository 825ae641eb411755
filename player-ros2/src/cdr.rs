//! ROS 2's serialized form of a message: the 4-byte encapsulation header (CDR, little-endian)
//! then the message in CDR, aligned from the header's end — what a DDS sample and a rosbag2
//! record hold.

use serde::Serialize;

/// CDR_LE: representation identifier 0x0001, options 0.
const ENCAPSULATION: [u8; 4] = [0x00, 0x01, 0x00, 0x00];

/// Why a message could not be serialized (a type serde cannot write as CDR).
#[derive(Debug, thiserror::Error)]
#[error("cannot serialize a ROS 2 message as CDR: {0}")]
pub struct CdrError(String);

/// `message` as ROS 2 serializes it.
pub fn serialize<T: Serialize>(message: &T) -> Result<Vec<u8>, CdrError> {
    let body = cdr_encoding::to_vec::<T, byteorder::LittleEndian>(message)
        .map_err(|e| CdrError(e.to_string()))?;
    let mut out = Vec::with_capacity(ENCAPSULATION.len() + body.len());
    out.extend_from_slice(&ENCAPSULATION);
    out.extend_from_slice(&body);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::msgs::{Header, Time};

    #[test]
    fn a_header_is_its_stamp_then_its_frame_counted_with_its_terminator() {
        let header = Header::new(Time { sec: 1, nanosec: 2 }, "ab");
        assert_eq!(
            serialize(&header).unwrap(),
            [
                0, 1, 0, 0, // CDR, little-endian
                1, 0, 0, 0, 2, 0, 0, 0, // stamp
                3, 0, 0, 0, b'a', b'b', 0, // "ab" and its NUL
            ]
        );
    }

    #[test]
    fn doubles_align_to_eight_from_the_encapsulation_s_end() {
        // A string of 1 + NUL ends at 6; the f64 after it starts at 8, not at 12.
        #[derive(serde::Serialize)]
        struct Probe {
            name: String,
            x: f64,
        }
        let bytes = serialize(&Probe {
            name: "a".into(),
            x: 1.0,
        })
        .unwrap();
        assert_eq!(bytes.len(), 4 + 8 + 8);
        assert_eq!(&bytes[12..], &1.0f64.to_le_bytes());
    }
}

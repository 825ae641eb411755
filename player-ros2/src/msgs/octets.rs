//! `uint8[]` fields (pixels, a cloud's points) written and read as one run of bytes: in CDR
//! the same length and bytes as a sequence of `u8`, without serde visiting every byte as a
//! number of its own (a 181-point cloud is 2 896 bytes, 640 of them a second for 64 robots).
//! Used as `#[serde(with = "octets")]`.

use serde::de::{Deserializer, SeqAccess, Visitor};
use serde::ser::Serializer;

pub fn serialize<S: Serializer>(bytes: &[u8], serializer: S) -> Result<S::Ok, S::Error> {
    serializer.serialize_bytes(bytes)
}

pub fn deserialize<'de, D: Deserializer<'de>>(deserializer: D) -> Result<Vec<u8>, D::Error> {
    deserializer.deserialize_byte_buf(Octets)
}

struct Octets;

impl<'de> Visitor<'de> for Octets {
    type Value = Vec<u8>;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a sequence of bytes")
    }

    fn visit_bytes<E>(self, v: &[u8]) -> Result<Vec<u8>, E> {
        Ok(v.to_vec())
    }

    fn visit_byte_buf<E>(self, v: Vec<u8>) -> Result<Vec<u8>, E> {
        Ok(v)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<u8>, A::Error> {
        let mut out = Vec::with_capacity(seq.size_hint().unwrap_or(0).min(1 << 20));
        while let Some(b) = seq.next_element()? {
            out.push(b);
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use serde::{Deserialize, Serialize};

    #[derive(Serialize, Deserialize, PartialEq, Debug)]
    struct AsBytes {
        name: String,
        #[serde(with = "super")]
        data: Vec<u8>,
    }

    #[derive(Serialize)]
    struct AsNumbers {
        name: String,
        data: Vec<u8>,
    }

    #[test]
    fn bytes_are_written_as_a_sequence_of_u8_is_and_read_back() {
        let fast = AsBytes {
            name: "ab".into(),
            data: vec![1, 2, 3, 250],
        };
        let slow = AsNumbers {
            name: "ab".into(),
            data: fast.data.clone(),
        };
        let bytes = crate::cdr::serialize(&fast).unwrap();
        assert_eq!(bytes, crate::cdr::serialize(&slow).unwrap());
        let back: AsBytes =
            cdr_encoding::from_bytes::<AsBytes, byteorder::LittleEndian>(&bytes[4..])
                .unwrap()
                .0;
        assert_eq!(back, fast);
    }
}

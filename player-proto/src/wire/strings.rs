//! Byte arrays and strings as Player sends them: counted, packed, padded.

use std::fmt;

use bytes::Bytes;

/// A counted byte array (`uint8_t *x` with `x_count`): camera pixels, map tiles, opaque data.
///
/// Holds a [`Bytes`] so that decoding a camera frame shares the received buffer instead of
/// copying it.
#[derive(Clone, PartialEq, Eq, Default)]
pub struct Opaque(pub Bytes);

impl Opaque {
    pub fn len(&self) -> usize {
        self.0.len()
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

impl fmt::Debug for Opaque {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Opaque({} bytes)", self.0.len())
    }
}

impl From<Vec<u8>> for Opaque {
    fn from(v: Vec<u8>) -> Self {
        Self(Bytes::from(v))
    }
}

impl std::ops::Deref for Opaque {
    type Target = [u8];
    fn deref(&self) -> &[u8] {
        &self.0
    }
}

/// A string sent as a counted byte array (`char *name` with `name_count`).
///
/// Player 2.1/3.x count the terminating NUL (`"stage"` travels as 6 bytes), Player 2.0 did
/// not. We keep the bytes exactly as they arrived, so a message re-encodes byte for byte,
/// and [`PlayerString::as_str`] shows the text without its NUL.
#[derive(Clone, PartialEq, Eq, Default)]
pub struct PlayerString(Bytes);

impl PlayerString {
    /// A string as Player 3.x sends it: the text followed by one NUL.
    pub fn new(text: &str) -> Self {
        let mut bytes = Vec::with_capacity(text.len() + 1);
        bytes.extend_from_slice(text.as_bytes());
        bytes.push(0);
        Self(Bytes::from(bytes))
    }

    /// Wraps bytes exactly as received.
    pub fn from_wire(bytes: Bytes) -> Self {
        Self(bytes)
    }

    /// The bytes as they travel, NUL included if there was one.
    pub fn wire_bytes(&self) -> &[u8] {
        &self.0
    }

    /// The text up to the first NUL. Invalid UTF-8 is replaced, never an error: a driver name
    /// is for showing, not for trusting.
    pub fn as_str(&self) -> std::borrow::Cow<'_, str> {
        let end = self.0.iter().position(|&b| b == 0).unwrap_or(self.0.len());
        String::from_utf8_lossy(&self.0[..end])
    }
}

impl fmt::Debug for PlayerString {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", self.as_str())
    }
}

impl fmt::Display for PlayerString {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.as_str())
    }
}

impl From<&str> for PlayerString {
    fn from(text: &str) -> Self {
        Self::new(text)
    }
}

#[cfg(any(test, feature = "proptest"))]
mod arbitrary {
    use super::*;
    use proptest::prelude::*;

    impl Arbitrary for Opaque {
        type Parameters = ();
        type Strategy = BoxedStrategy<Self>;
        fn arbitrary_with(_: ()) -> Self::Strategy {
            proptest::collection::vec(any::<u8>(), 0..64)
                .prop_map(Opaque::from)
                .boxed()
        }
    }

    impl Arbitrary for PlayerString {
        type Parameters = ();
        type Strategy = BoxedStrategy<Self>;
        fn arbitrary_with(_: ()) -> Self::Strategy {
            // Both conventions occur on real links: with and without the trailing NUL.
            (proptest::collection::vec(any::<u8>(), 0..40), any::<bool>())
                .prop_map(|(mut v, nul)| {
                    if nul {
                        v.push(0);
                    }
                    PlayerString(Bytes::from(v))
                })
                .boxed()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_stops_at_the_nul() {
        let name = PlayerString::new("stage");
        assert_eq!(name.wire_bytes(), b"stage\0");
        assert_eq!(name.as_str(), "stage");
        assert_eq!(
            PlayerString::from_wire(Bytes::from_static(b"stage")).as_str(),
            "stage"
        );
    }
}

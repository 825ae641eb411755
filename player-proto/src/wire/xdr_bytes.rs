//! Byte arrays as Player packs them: counted (`uint8_t *x` with `x_count`: count, length,
//! bytes, zero padding to 4) or fixed (`char x[N]`: exactly N bytes and padding). Unlike every
//! other array they take one byte per element, and they come back as zero-copy slices of the
//! received body where possible.

use bytes::{BufMut, Bytes};

use super::strings::{Opaque, PlayerString};
use super::xdr_codec::{Xdr, XdrFault, XdrResult, counted_length, fail};

/// Bytes needed to pad `len` up to the next multiple of 4.
#[inline]
pub const fn pad4(len: usize) -> usize {
    (4 - len % 4) % 4
}

/// Decodes a counted byte array (`uint32_t x_count; uint8_t *x;`): count, length, packed
/// bytes, padding. The bytes come back as a zero-copy slice of `body` when possible.
/// Inlined, like the decoders of the structs holding byte arrays (see `xdr_struct!`).
#[inline(always)]
pub fn decode_counted_bytes<'a>(input: &'a [u8], body: &Bytes) -> XdrResult<'a, Bytes> {
    let (rest, bytes) = view_counted_bytes(input)?;
    Ok((rest, share_or_copy(body, bytes)))
}

/// Decodes `len` packed bytes and their padding from `rest`. `length_at` is where the length
/// was read, for error offsets.
#[inline(always)]
pub fn decode_packed_bytes<'a>(
    length_at: &'a [u8],
    rest: &'a [u8],
    len: usize,
    body: &Bytes,
) -> XdrResult<'a, Bytes> {
    let (rest, bytes) = view_packed_bytes(length_at, rest, len)?;
    Ok((rest, share_or_copy(body, bytes)))
}

/// Writes a counted byte array: count, length, bytes, zero padding.
pub fn encode_counted_bytes<B: BufMut>(bytes: &[u8], out: &mut B) {
    let n = u32::try_from(bytes.len()).expect("byte array longer than u32::MAX");
    out.put_u32(n);
    encode_packed_bytes(bytes, out);
}

/// Writes XDR's own length prefix, the bytes and their zero padding.
pub fn encode_packed_bytes<B: BufMut>(bytes: &[u8], out: &mut B) {
    let n = u32::try_from(bytes.len()).expect("byte array longer than u32::MAX");
    out.put_u32(n);
    out.put_slice(bytes);
    out.put_bytes(0, pad4(bytes.len()));
}

/// Counted bytes (`uint8_t *x` with `x_count`): count, length, bytes, padding — the same checks
/// as [`decode_counted_bytes`], returning the bytes in place.
#[inline(always)]
pub fn view_counted_bytes(input: &[u8]) -> XdrResult<'_, &[u8]> {
    let (rest, len) = counted_length(input, 1)?;
    // The length was read 4 bytes in: where a padding that does not fit is reported.
    view_packed_bytes(&input[4..], rest, len)
}

/// `len` packed bytes and their padding from `rest`; `length_at` is where the length was read,
/// for the error's offset.
#[inline(always)]
pub fn view_packed_bytes<'a>(
    length_at: &'a [u8],
    rest: &'a [u8],
    len: usize,
) -> XdrResult<'a, &'a [u8]> {
    let padded = len.saturating_add(pad4(len));
    if padded > rest.len() {
        return fail(
            length_at,
            XdrFault::LengthBeyondBody {
                length: u32::try_from(len).unwrap_or(u32::MAX),
                remaining: rest.len(),
            },
        );
    }
    Ok((&rest[padded..], &rest[..len]))
}

/// A zero-copy slice of `body` when `part` lies inside it, a copy otherwise.
#[inline(always)]
fn share_or_copy(body: &Bytes, part: &[u8]) -> Bytes {
    let start = body.as_ptr() as usize;
    let at = part.as_ptr() as usize;
    if at >= start && at + part.len() <= start + body.len() {
        body.slice_ref(part)
    } else {
        Bytes::copy_from_slice(part)
    }
}

impl Xdr for Opaque {
    const MIN_WIRE_SIZE: usize = 8;

    #[inline(always)]
    fn decode<'a>(input: &'a [u8], body: &Bytes) -> XdrResult<'a, Self> {
        let (rest, bytes) = decode_counted_bytes(input, body)?;
        Ok((rest, Opaque(bytes)))
    }

    fn encode<B: BufMut>(&self, out: &mut B) {
        encode_counted_bytes(&self.0, out);
    }

    fn encoded_len(&self) -> usize {
        8 + self.0.len() + pad4(self.0.len())
    }
}

impl Xdr for PlayerString {
    const MIN_WIRE_SIZE: usize = 8;

    fn decode<'a>(input: &'a [u8], body: &Bytes) -> XdrResult<'a, Self> {
        let (rest, bytes) = decode_counted_bytes(input, body)?;
        Ok((rest, PlayerString::from_wire(bytes)))
    }

    fn encode<B: BufMut>(&self, out: &mut B) {
        encode_counted_bytes(self.wire_bytes(), out);
    }

    fn encoded_len(&self) -> usize {
        let n = self.wire_bytes().len();
        8 + n + pad4(n)
    }
}

/// A fixed byte array without a count (`char ap[32]`): exactly `N` packed bytes plus padding.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FixedBytes<const N: usize>(pub [u8; N]);

impl<const N: usize> Default for FixedBytes<N> {
    fn default() -> Self {
        Self([0; N])
    }
}

impl<const N: usize> Xdr for FixedBytes<N> {
    const MIN_WIRE_SIZE: usize = N + pad4(N);

    fn decode<'a>(input: &'a [u8], _: &Bytes) -> XdrResult<'a, Self> {
        let total = N + pad4(N);
        if input.len() < total {
            return fail(input, XdrFault::Truncated);
        }
        let mut bytes = [0; N];
        bytes.copy_from_slice(&input[..N]);
        Ok((&input[total..], Self(bytes)))
    }

    fn encode<B: BufMut>(&self, out: &mut B) {
        out.put_slice(&self.0);
        out.put_bytes(0, pad4(N));
    }

    fn encoded_len(&self) -> usize {
        N + pad4(N)
    }
}

#[cfg(any(test, feature = "proptest"))]
impl<const N: usize> proptest::arbitrary::Arbitrary for FixedBytes<N> {
    type Parameters = ();
    type Strategy = proptest::strategy::BoxedStrategy<Self>;

    fn arbitrary_with(_: ()) -> Self::Strategy {
        use proptest::strategy::Strategy;
        proptest::collection::vec(proptest::arbitrary::any::<u8>(), N)
            .prop_map(|v| {
                let mut bytes = [0; N];
                bytes.copy_from_slice(&v);
                Self(bytes)
            })
            .boxed()
    }
}

//! The [`Xdr`] trait, its errors and its arrays: the bottom of the codec, which the byte arrays
//! ([`super::xdr_bytes`]), the numbers and the views ([`super::xdr_view`]) build on, apart from
//! [`super::xdr`], which gathers all of them, so that none of them depends on what it gathers.

use bytes::{BufMut, Bytes};
use nom::error::{ErrorKind, ParseError};

/// The result of decoding one XDR item: the remaining input and the value.
pub type XdrResult<'a, T> = nom::IResult<&'a [u8], T, XdrError<'a>>;

/// Why an XDR item could not be decoded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum XdrFault {
    /// The body ended before the item did.
    Truncated,
    /// An array's XDR length prefix is larger than the `x_count` member before it
    /// (Player's own decoder refuses this too).
    LengthAboveCount { count: u32, length: u32 },
    /// An array length that cannot fit in the bytes that are left: refused before allocating.
    LengthBeyondBody { length: u32, remaining: usize },
    /// A bounded array (`T x[MAX]` with a count, e.g. a device list of at most 4096) whose
    /// length exceeds its maximum; Player's decoder refuses it too.
    LengthAboveMax { length: u32, max: u32 },
    /// Any other combinator failure.
    Malformed,
}

/// A decoding failure, carrying the input that was left when it happened so that the caller
/// can turn it into a byte offset within the message body.
#[derive(Debug, Clone, PartialEq)]
pub struct XdrError<'a> {
    /// Input remaining at the failure point.
    pub input: &'a [u8],
    pub fault: XdrFault,
    /// Innermost struct field being decoded, when known (`"ranges"`).
    pub field: Option<&'static str>,
    /// Type that field belongs to (`"LaserScan"`).
    pub within: Option<&'static str>,
}

impl<'a> XdrError<'a> {
    pub fn new(input: &'a [u8], fault: XdrFault) -> Self {
        Self {
            input,
            fault,
            field: None,
            within: None,
        }
    }

    /// Records the innermost field and type being decoded; outer structs leave it as it is.
    pub fn in_field(mut self, within: &'static str, field: &'static str) -> Self {
        if self.field.is_none() {
            self.field = Some(field);
            self.within = Some(within);
        }
        self
    }
}

impl<'a> ParseError<&'a [u8]> for XdrError<'a> {
    fn from_error_kind(input: &'a [u8], kind: ErrorKind) -> Self {
        let fault = match kind {
            ErrorKind::Eof | ErrorKind::Complete => XdrFault::Truncated,
            _ => XdrFault::Malformed,
        };
        Self::new(input, fault)
    }

    fn append(_: &'a [u8], _: ErrorKind, other: Self) -> Self {
        other
    }
}

/// Fails with `fault` at `input`.
pub fn fail<'a, T>(input: &'a [u8], fault: XdrFault) -> XdrResult<'a, T> {
    Err(nom::Err::Error(XdrError::new(input, fault)))
}

/// Adds field context to an error bubbling up from a struct member.
pub fn in_field<'a>(
    err: nom::Err<XdrError<'a>>,
    within: &'static str,
    field: &'static str,
) -> nom::Err<XdrError<'a>> {
    err.map(|e| e.in_field(within, field))
}

/// Checks the XDR length of the counted array at the front of `input` (count word, then
/// length word) against the array's declared maximum, before anything is decoded. Like
/// Player's decoder it judges the inner length; the outer count of a fixed array is ignored
/// there. Input too short to hold the two words passes: decoding the array reports that.
pub fn check_max_length(input: &[u8], max: u32) -> Result<(), nom::Err<XdrError<'_>>> {
    let Some(length_at) = input.get(4..) else {
        return Ok(());
    };
    let Some(word) = length_at.get(..4) else {
        return Ok(());
    };
    let length = u32::from_be_bytes(word.try_into().expect("4 bytes"));
    if length > max {
        return Err(nom::Err::Error(XdrError::new(
            length_at,
            XdrFault::LengthAboveMax { length, max },
        )));
    }
    Ok(())
}

/// A value with a Player XDR encoding.
pub trait Xdr: Sized {
    /// The fewest bytes any value of this type occupies on the wire. Used to refuse an array
    /// length before allocating for it.
    const MIN_WIRE_SIZE: usize;

    /// Decodes one value from the front of `input`. `body` is the whole message body that
    /// `input` is a slice of, so byte arrays can be returned without copying.
    fn decode<'a>(input: &'a [u8], body: &Bytes) -> XdrResult<'a, Self>;

    /// Appends the wire encoding.
    fn encode<B: BufMut>(&self, out: &mut B);

    /// The exact number of bytes [`Xdr::encode`] writes.
    fn encoded_len(&self) -> usize;
}

/// Types that may be elements of a counted XDR array (`Vec<T>`) or a fixed vector (`[T; N]`).
///
/// Byte types are deliberately not elements: Player packs byte arrays (see [`Opaque`]), while a
/// `Vec<u8>` decoded element by element would take 4 bytes per byte.
pub trait XdrElement: Xdr {
    /// Decodes `n` consecutive elements. The default goes element by element through the
    /// parser; primitive numbers override it with one tight loop over the raw bytes.
    fn decode_many<'a>(
        mut input: &'a [u8],
        body: &Bytes,
        n: usize,
        out: &mut Vec<Self>,
    ) -> XdrResult<'a, ()> {
        for _ in 0..n {
            let (rest, item) = Self::decode(input, body)?;
            out.push(item);
            input = rest;
        }
        Ok((input, ()))
    }

    /// Decodes `out.len()` consecutive elements into `out` (a fixed vector), without
    /// allocating. Primitive numbers override it with one loop over the raw bytes.
    fn decode_into<'a>(mut input: &'a [u8], body: &Bytes, out: &mut [Self]) -> XdrResult<'a, ()> {
        for slot in out {
            let (rest, item) = Self::decode(input, body)?;
            *slot = item;
            input = rest;
        }
        Ok((input, ()))
    }
}

/// The length of the counted array at the front of `input` (the `x_count` member, then XDR's
/// own length), checked before anything is allocated or read for it: not above the count, and
/// not more elements of at least `element_size` bytes than the bytes left can hold. Returns
/// the input after the two words.
#[inline(always)]
pub fn counted_length(input: &[u8], element_size: usize) -> XdrResult<'_, usize> {
    // Numbers hold no byte array, so the body handle is never used.
    let (after_count, count) = u32::decode(input, &Bytes::new())?;
    let (rest, length) = u32::decode(after_count, &Bytes::new())?;
    if length > count {
        return fail(after_count, XdrFault::LengthAboveCount { count, length });
    }
    let n = length as usize;
    if n.saturating_mul(element_size.max(1)) > rest.len() {
        return fail(
            after_count,
            XdrFault::LengthBeyondBody {
                length,
                remaining: rest.len(),
            },
        );
    }
    Ok((rest, n))
}

/// A counted array (`uint32_t x_count; T *x;`): the count member, XDR's length prefix, then
/// the elements.
impl<T: XdrElement> Xdr for Vec<T> {
    const MIN_WIRE_SIZE: usize = 8;

    // Inlined like the structs holding it (see `xdr_struct!`).
    #[inline(always)]
    fn decode<'a>(input: &'a [u8], body: &Bytes) -> XdrResult<'a, Self> {
        let (rest, n) = counted_length(input, T::MIN_WIRE_SIZE)?;
        let mut items = Vec::with_capacity(n);
        let (rest, ()) = T::decode_many(rest, body, n, &mut items)?;
        Ok((rest, items))
    }

    fn encode<B: BufMut>(&self, out: &mut B) {
        let n = u32::try_from(self.len()).expect("array longer than u32::MAX");
        out.put_u32(n);
        out.put_u32(n);
        for item in self {
            item.encode(out);
        }
    }

    fn encoded_len(&self) -> usize {
        8 + self.iter().map(Xdr::encoded_len).sum::<usize>()
    }
}

/// A fixed vector (`double cov[6]`): exactly `N` elements and no length prefix.
impl<T: XdrElement + Default + Copy, const N: usize> Xdr for [T; N] {
    const MIN_WIRE_SIZE: usize = N * T::MIN_WIRE_SIZE;

    fn decode<'a>(input: &'a [u8], body: &Bytes) -> XdrResult<'a, Self> {
        let mut array = [T::default(); N];
        let (rest, ()) = T::decode_into(input, body, &mut array)?;
        Ok((rest, array))
    }

    fn encode<B: BufMut>(&self, out: &mut B) {
        for item in self {
            item.encode(out);
        }
    }

    fn encoded_len(&self) -> usize {
        self.iter().map(Xdr::encoded_len).sum()
    }
}

/// Decodes a whole value from `body` and checks nothing was left over.
///
/// Player itself skips trailing bytes silently; we report how many there were so the caller
/// can log them. Always inlined, like every struct's decoder, so that a decoded value is built
/// in the caller's place.
#[inline(always)]
pub fn decode_all<T: Xdr>(body: &Bytes) -> Result<(T, usize), XdrError<'_>> {
    match T::decode(body, body) {
        Ok((rest, value)) => Ok((value, rest.len())),
        Err(nom::Err::Error(e) | nom::Err::Failure(e)) => Err(e),
        Err(nom::Err::Incomplete(_)) => {
            Err(XdrError::new(&body[body.len()..], XdrFault::Truncated))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wire::Opaque;

    fn encode<T: Xdr>(value: &T) -> Vec<u8> {
        let mut out = Vec::new();
        value.encode(&mut out);
        assert_eq!(out.len(), value.encoded_len());
        out
    }

    #[test]
    fn small_integers_are_widened() {
        assert_eq!(encode(&7u8), [0, 0, 0, 7]);
        assert_eq!(encode(&-1i8), [0xff; 4]);
        assert_eq!(encode(&0x1234u16), [0, 0, 0x12, 0x34]);
        let body = Bytes::from_static(&[0, 0, 1, 7]);
        // Player keeps the low 8 bits without complaint.
        assert_eq!(u8::decode(&body, &body).unwrap().1, 7);
    }

    #[test]
    fn counted_array_repeats_its_count() {
        assert_eq!(
            encode(&vec![1.0f32, 2.5]),
            [0, 0, 0, 2, 0, 0, 0, 2, 0x3f, 0x80, 0, 0, 0x40, 0x20, 0, 0]
        );
    }

    #[test]
    fn byte_arrays_are_packed_and_padded() {
        let encoded = encode(&Opaque(Bytes::from_static(&[1, 0xff])));
        assert_eq!(encoded, [0, 0, 0, 2, 0, 0, 0, 2, 1, 0xff, 0, 0]);
        let body = Bytes::from(encoded);
        let (rest, back) = Opaque::decode(&body, &body).unwrap();
        assert!(rest.is_empty());
        assert_eq!(&back.0[..], &[1, 0xff]);
    }

    #[test]
    fn lying_length_is_refused_before_allocating() {
        // count and length both claim 2^30 floats, but only 4 bytes follow.
        let body = Bytes::from_static(&[0x40, 0, 0, 0, 0x40, 0, 0, 0, 0, 0, 0, 0]);
        let err = decode_all::<Vec<f32>>(&body).unwrap_err();
        assert!(matches!(err.fault, XdrFault::LengthBeyondBody { .. }));
    }

    #[test]
    fn length_above_count_is_refused() {
        let body = Bytes::from_static(&[0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0]);
        let err = decode_all::<Vec<u32>>(&body).unwrap_err();
        assert_eq!(
            err.fault,
            XdrFault::LengthAboveCount {
                count: 1,
                length: 2
            }
        );
    }

    #[test]
    fn bulk_arrays_decode_like_one_element_at_a_time() {
        // Lengths either side of the AVX2 threshold and of its 32-word rounds.
        for words in [0, 1, 7, 31, 32, 33, 63, 64, 65, 181, 361] {
            let raw: Vec<u8> = (0..words * 8).map(|i| (i * 37 % 251) as u8).collect();
            let body = Bytes::from(raw.clone());
            let one_by_one = |size: usize| raw[..words * size].chunks_exact(size);
            let (rest, floats) = decode_n::<f32>(&body, words);
            assert_eq!(rest, words * 4);
            let expected: Vec<u32> = one_by_one(4)
                .map(|c| u32::from_be_bytes(c.try_into().unwrap()))
                .collect();
            assert_eq!(
                floats.iter().map(|f| f.to_bits()).collect::<Vec<_>>(),
                expected
            );
            assert_eq!(decode_n::<u32>(&body, words).1, expected);
            let (rest, doubles) = decode_n::<f64>(&body, words);
            assert_eq!(rest, 0);
            let expected: Vec<u64> = one_by_one(8)
                .map(|c| u64::from_be_bytes(c.try_into().unwrap()))
                .collect();
            assert_eq!(
                doubles.iter().map(|f| f.to_bits()).collect::<Vec<_>>(),
                expected
            );
        }
    }

    /// Decodes `n` elements from the front of `body`; returns the bytes left and the values.
    fn decode_n<T: XdrElement>(body: &Bytes, n: usize) -> (usize, Vec<T>) {
        let mut out = Vec::with_capacity(n);
        let (rest, ()) = T::decode_many(body, body, n, &mut out).unwrap();
        (rest.len(), out)
    }

    #[test]
    fn bulk_array_longer_than_its_input_is_truncated() {
        let body = Bytes::from_static(&[0; 12]);
        let mut out = Vec::new();
        let err = f32::decode_many(&body, &body, 4, &mut out).unwrap_err();
        assert!(matches!(err, nom::Err::Error(e) if e.fault == XdrFault::Truncated));
        assert!(out.is_empty());
        let mut doubles = Vec::new();
        // n * 8 overflows usize: still just too short.
        let err = f64::decode_many(&body, &body, usize::MAX / 4, &mut doubles).unwrap_err();
        assert!(matches!(err, nom::Err::Error(e) if e.fault == XdrFault::Truncated));
    }

    #[test]
    fn fixed_vectors_have_no_prefix() {
        assert_eq!(encode(&[1i32, 2]), [0, 0, 0, 1, 0, 0, 0, 2]);
        let body = Bytes::from(encode(&[1.5f64, -2.0, 3.25]));
        assert_eq!(
            decode_all::<[f64; 3]>(&body).unwrap(),
            ([1.5, -2.0, 3.25], 0)
        );
        let short = body.slice(..23);
        let err = decode_all::<[f64; 3]>(&short).unwrap_err();
        assert_eq!((err.fault, err.input.len()), (XdrFault::Truncated, 23));
        // 16-bit numbers go element by element.
        let body = Bytes::from(encode(&[1u16, 2, 3]));
        assert_eq!(decode_all::<[u16; 3]>(&body).unwrap(), ([1, 2, 3], 0));
        let short = body.slice(..11);
        let err = decode_all::<[u16; 3]>(&short).unwrap_err();
        assert_eq!((err.fault, err.input.len()), (XdrFault::Truncated, 3));
    }
}

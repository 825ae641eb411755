//! Reading a body where it lies: a *view* of a message checks the whole body as the decoder
//! would, then hands out its numbers from the received bytes, with no allocation and no
//! handle on the buffer.
//!
//! An owned message costs an allocation per array and, for byte arrays, a counted handle on
//! the receive buffer (an atomic increment and decrement); both are fixed costs that dwarf the
//! work of converting a few hundred big-endian numbers. Code that looks at a message and lets
//! it go — a converter to another format, a relay, a counter — reads a view instead and pays
//! only for what it reads. Code that keeps a message decodes it ([`Xdr::decode`]) or turns a
//! view into the owned value ([`XdrView::to_owned_value`]).
//!
//! Every struct declared with `xdr_struct!` gets a view (`LaserScan` → `LaserScanView`) whose
//! fields are its fields' views: numbers as numbers, arrays as [`XdrArray`], byte arrays as
//! byte slices. A view is refused exactly where, and with the same fault, as decoding the same
//! bytes is, so a view that was made can be read without any further checks.

use std::fmt;
use std::marker::PhantomData;

use bytes::Bytes;

use super::strings::{Opaque, PlayerString};
use super::xdr_bytes::{FixedBytes, pad4};
pub use super::xdr_bytes::{view_counted_bytes, view_packed_bytes};
use super::xdr_codec::{Xdr, XdrElement, XdrFault, XdrResult, counted_length, fail};

/// The borrowed reading of `T` from bytes that live for `'a`.
pub type View<'a, T> = <T as XdrView>::View<'a>;

/// A value with a borrowed reading of its wire form.
pub trait XdrView: Xdr {
    /// The value as read in place. Copy: it holds numbers and slices of the body only.
    type View<'a>: Copy + fmt::Debug;

    /// The size every value of this type takes on the wire, when it is the same for all of
    /// them and any bytes of that size are a value (numbers, fixed vectors, structs of those):
    /// an array of them is then checked by its length and indexed, not walked.
    const FIXED_SIZE: Option<usize>;

    /// Checks the value at the front of `input` exactly as [`Xdr::decode`] would and returns
    /// its view and the input after it.
    fn view(input: &[u8]) -> XdrResult<'_, Self::View<'_>>;

    /// The owned value a view reads (what [`Xdr::decode`] of the same bytes returns; byte
    /// arrays are copied rather than shared).
    fn to_owned_value(view: Self::View<'_>) -> Self;
}

/// Sum of the fixed sizes of a struct's fields: fixed only if every field is.
pub const fn fixed_sum(sizes: &[Option<usize>]) -> Option<usize> {
    let mut total = 0;
    let mut i = 0;
    while i < sizes.len() {
        match sizes[i] {
            Some(n) => total += n,
            None => return None,
        }
        i += 1;
    }
    Some(total)
}

/// Types whose view is the value itself: numbers and the fixed-size types made of them.
macro_rules! view_as_value {
    ($($ty:ty),* $(,)?) => {$(
        impl XdrView for $ty {
            type View<'a> = $ty;
            const FIXED_SIZE: Option<usize> = Some(<$ty as Xdr>::MIN_WIRE_SIZE);

            #[inline(always)]
            fn view(input: &[u8]) -> XdrResult<'_, $ty> {
                // Fixed-size values hold no byte array, so the body handle is never used.
                <$ty as Xdr>::decode(input, &Bytes::new())
            }

            #[inline(always)]
            fn to_owned_value(view: $ty) -> $ty {
                view
            }
        }
    )*};
}

view_as_value!(u8, i8, u16, i16, u32, i32, f32, f64, i64, super::DevAddr);

impl<const N: usize> XdrView for FixedBytes<N> {
    type View<'a> = FixedBytes<N>;
    const FIXED_SIZE: Option<usize> = Some(N + pad4(N));

    fn view(input: &[u8]) -> XdrResult<'_, Self> {
        Self::decode(input, &Bytes::new())
    }

    fn to_owned_value(view: Self) -> Self {
        view
    }
}

impl<T: XdrElement + XdrView + Default + Copy + fmt::Debug, const N: usize> XdrView for [T; N] {
    type View<'a> = [T; N];
    const FIXED_SIZE: Option<usize> = match T::FIXED_SIZE {
        Some(n) => Some(n * N),
        None => None,
    };

    fn view(input: &[u8]) -> XdrResult<'_, Self> {
        // Copy elements are values with no byte array inside: decoding borrows nothing.
        Self::decode(input, &Bytes::new())
    }

    fn to_owned_value(view: Self) -> Self {
        view
    }
}

impl XdrView for Opaque {
    type View<'a> = &'a [u8];
    const FIXED_SIZE: Option<usize> = None;

    #[inline(always)]
    fn view(input: &[u8]) -> XdrResult<'_, &[u8]> {
        view_counted_bytes(input)
    }

    fn to_owned_value(view: &[u8]) -> Opaque {
        Opaque(Bytes::copy_from_slice(view))
    }
}

/// A string's view is its bytes as they travel (a C string: up to its first NUL, Latin-1 or
/// UTF-8 as the server wrote it); [`PlayerString`] is what interprets them.
impl XdrView for PlayerString {
    type View<'a> = &'a [u8];
    const FIXED_SIZE: Option<usize> = None;

    fn view(input: &[u8]) -> XdrResult<'_, &[u8]> {
        view_counted_bytes(input)
    }

    fn to_owned_value(view: &[u8]) -> PlayerString {
        PlayerString::from_wire(Bytes::copy_from_slice(view))
    }
}

/// A counted array (`uint32_t x_count; T *x;`) read in place: its elements' bytes, checked.
pub struct XdrArray<'a, T> {
    /// The elements' bytes, exactly (no count, no length, nothing after).
    raw: &'a [u8],
    len: usize,
    element: PhantomData<fn() -> T>,
}

// Manual impls: derives would ask the same of `T`, though only a slice is held.
impl<T> Clone for XdrArray<'_, T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<T> Copy for XdrArray<'_, T> {}

impl<T: XdrView> fmt::Debug for XdrArray<'_, T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

impl<'a, T: XdrView> XdrArray<'a, T> {
    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Element `i`'s view (`None` past the end). Indexed for fixed-size elements, walked from
    /// the start otherwise.
    pub fn get(&self, i: usize) -> Option<T::View<'a>> {
        if i >= self.len {
            return None;
        }
        match T::FIXED_SIZE {
            Some(size) => self.raw.get(i * size..).and_then(|at| element::<T>(at)),
            None => self.iter().nth(i),
        }
    }

    /// The elements' views, in order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = T::View<'a>> {
        Elements::<T> {
            rest: self.raw,
            left: self.len,
            element: PhantomData,
        }
    }

    /// The elements' bytes as they travel (big-endian numbers, padding and all).
    pub fn wire_bytes(&self) -> &'a [u8] {
        self.raw
    }
}

impl<T: XdrView + XdrElement> XdrArray<'_, T> {
    /// Appends the elements, decoded, to `out`: one pass over the bytes for numbers (the same
    /// conversion as decoding an owned array), with no allocation when `out` has room.
    pub fn extend_into(&self, out: &mut Vec<T>) {
        out.reserve(self.len);
        // The bytes were checked when the view was made: this cannot fail. Were it to, `out`
        // would just hold fewer elements.
        let _ = T::decode_many(self.raw, &Bytes::new(), self.len, out);
    }

    /// The elements as an owned vector.
    pub fn to_vec(&self) -> Vec<T> {
        let mut out = Vec::with_capacity(self.len);
        self.extend_into(&mut out);
        out
    }
}

/// Element at the front of `at`, already checked when the array's view was made.
#[inline(always)]
fn element<T: XdrView>(at: &[u8]) -> Option<T::View<'_>> {
    T::view(at).ok().map(|(_, value)| value)
}

struct Elements<'a, T> {
    rest: &'a [u8],
    left: usize,
    element: PhantomData<fn() -> T>,
}

impl<'a, T: XdrView> Iterator for Elements<'a, T> {
    type Item = T::View<'a>;

    #[inline]
    fn next(&mut self) -> Option<T::View<'a>> {
        if self.left == 0 {
            return None;
        }
        let (rest, value) = T::view(self.rest).ok()?;
        self.rest = rest;
        self.left -= 1;
        Some(value)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        (self.left, Some(self.left))
    }
}

impl<T: XdrView> ExactSizeIterator for Elements<'_, T> {}

impl<T: XdrElement + XdrView> XdrView for Vec<T> {
    type View<'a> = XdrArray<'a, T>;
    const FIXED_SIZE: Option<usize> = None;

    #[inline(always)]
    fn view(input: &[u8]) -> XdrResult<'_, XdrArray<'_, T>> {
        let (rest, n) = counted_length(input, T::MIN_WIRE_SIZE)?;
        let end = match T::FIXED_SIZE {
            // The check above, for these elements: they are MIN_WIRE_SIZE bytes each.
            Some(size) => match n.checked_mul(size).filter(|&len| len <= rest.len()) {
                Some(len) => len,
                None => return fail(rest, XdrFault::Truncated),
            },
            None => {
                let mut at = rest;
                for _ in 0..n {
                    at = T::view(at)?.0;
                }
                rest.len() - at.len()
            }
        };
        let (raw, after) = rest.split_at(end);
        Ok((
            after,
            XdrArray {
                raw,
                len: n,
                element: PhantomData,
            },
        ))
    }

    fn to_owned_value(view: XdrArray<'_, T>) -> Vec<T> {
        view.to_vec()
    }
}

/// Views the whole of `body` as `T`; bytes after it are let be, as Player lets them be.
#[inline(always)]
pub fn view_all<T: XdrView>(body: &[u8]) -> Result<T::View<'_>, super::XdrError<'_>> {
    match T::view(body) {
        Ok((_, value)) => Ok(value),
        Err(nom::Err::Error(e) | nom::Err::Failure(e)) => Err(e),
        Err(nom::Err::Incomplete(_)) => Err(super::XdrError::new(
            &body[body.len()..],
            XdrFault::Truncated,
        )),
    }
}

//! Numbers on the wire: the XDR codec of every scalar Player sends, and the bulk conversion
//! of arrays of them (the hot loop of decoding a laser scan or a ranger's readings).

use bytes::{BufMut, Bytes};

use super::xdr_codec::{Xdr, XdrElement, XdrFault, XdrResult, fail};

/// The next `N` bytes as an array. Scalars are read with this rather than nom's generic
/// number parsers, which assemble values byte by byte through trait calls: for a struct of
/// doubles (a fiducial's poses) that made decoding several times slower. Same result, same
/// `Truncated` error at the same place.
#[inline(always)]
fn take_word<const N: usize>(input: &[u8]) -> XdrResult<'_, [u8; N]> {
    match input.split_first_chunk::<N>() {
        Some((raw, rest)) => Ok((rest, *raw)),
        None => fail(input, XdrFault::Truncated),
    }
}

/// Numbers whose wire form is their own big-endian bytes; arrays of them decode in one loop.
macro_rules! xdr_number {
    ($ty:ty, $size:expr) => {
        impl Xdr for $ty {
            const MIN_WIRE_SIZE: usize = $size;
            #[inline]
            fn decode<'a>(input: &'a [u8], _: &Bytes) -> XdrResult<'a, Self> {
                let (rest, raw) = take_word::<$size>(input)?;
                Ok((rest, <$ty>::from_be_bytes(raw)))
            }
            #[inline]
            fn encode<B: BufMut>(&self, out: &mut B) {
                out.put_slice(&self.to_be_bytes());
            }
            #[inline]
            fn encoded_len(&self) -> usize {
                $size
            }
        }

        impl XdrElement for $ty {
            #[inline]
            fn decode_many<'a>(
                input: &'a [u8],
                _: &Bytes,
                n: usize,
                out: &mut Vec<Self>,
            ) -> XdrResult<'a, ()> {
                let Some((raw, rest)) = n
                    .checked_mul($size)
                    .and_then(|len| input.split_at_checked(len))
                else {
                    return fail(input, XdrFault::Truncated);
                };
                bulk::extend_from_be(raw, out);
                Ok((rest, ()))
            }

            #[inline]
            fn decode_into<'a>(input: &'a [u8], _: &Bytes, out: &mut [Self]) -> XdrResult<'a, ()> {
                let Some((raw, rest)) = out
                    .len()
                    .checked_mul($size)
                    .and_then(|len| input.split_at_checked(len))
                else {
                    return fail(input, XdrFault::Truncated);
                };
                for (slot, word) in out.iter_mut().zip(raw.chunks_exact($size)) {
                    *slot = <$ty>::from_be_bytes(word.try_into().expect("exact chunk"));
                }
                Ok((rest, ()))
            }
        }

        impl bulk::BeWord<$size> for $ty {
            #[inline(always)]
            fn from_be(raw: [u8; $size]) -> Self {
                <$ty>::from_be_bytes(raw)
            }
        }
    };
}

/// Arrays of numbers converted in one pass over the raw bytes.
///
/// The loop is `chunks_exact` + `from_be_bytes`, which LLVM vectorises. The byte swap is the
/// whole cost: with the baseline x86-64 instruction set (SSE2) it takes seven shuffles per 16
/// bytes, so a 361-beam laser scan spent more than half its decoding time there. With AVX2
/// it is one `vpshufb` per 32 bytes, so on x86-64 the same loop is also compiled for AVX2 and
/// chosen at run time when the CPU has it (every x86-64 CPU since about 2013 does).
mod bulk {
    /// A number whose wire form is its own `N` big-endian bytes.
    pub(super) trait BeWord<const N: usize>: Sized {
        fn from_be(raw: [u8; N]) -> Self;
    }

    /// Below this many bytes the AVX2 loop cannot run a single 128-byte round and the
    /// feature check is not worth making.
    #[cfg(all(target_arch = "x86_64", not(target_feature = "avx2")))]
    const AVX2_FROM: usize = 128;

    /// Appends the numbers in `raw` (a whole number of `N`-byte words) to `out`.
    #[inline]
    pub(super) fn extend_from_be<T: BeWord<N>, const N: usize>(raw: &[u8], out: &mut Vec<T>) {
        #[cfg(all(target_arch = "x86_64", not(target_feature = "avx2")))]
        if raw.len() >= AVX2_FROM && std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: `extend_avx2` only requires AVX2, which the CPU was just found to have.
            unsafe { extend_avx2(raw, out) };
            return;
        }
        extend(raw, out);
    }

    #[inline(always)]
    fn extend<T: BeWord<N>, const N: usize>(raw: &[u8], out: &mut Vec<T>) {
        out.extend(
            raw.chunks_exact(N)
                .map(|c| T::from_be(c.try_into().expect("exact chunk"))),
        );
    }

    /// The same loop compiled for AVX2.
    #[cfg(all(target_arch = "x86_64", not(target_feature = "avx2")))]
    #[target_feature(enable = "avx2")]
    fn extend_avx2<T: BeWord<N>, const N: usize>(raw: &[u8], out: &mut Vec<T>) {
        extend(raw, out);
    }
}

xdr_number!(u32, 4);
xdr_number!(i32, 4);
xdr_number!(f32, 4);
xdr_number!(f64, 8);
xdr_number!(i64, 8);

/// Small integers are widened to a 4-byte XDR int. On decode Player keeps only the low bits
/// without a range check, and so do we.
macro_rules! xdr_widened {
    ($ty:ty, $wide:ty) => {
        impl Xdr for $ty {
            const MIN_WIRE_SIZE: usize = 4;
            #[inline]
            fn decode<'a>(input: &'a [u8], _: &Bytes) -> XdrResult<'a, Self> {
                let (rest, raw) = take_word::<4>(input)?;
                Ok((rest, <$wide>::from_be_bytes(raw) as $ty))
            }
            #[inline]
            fn encode<B: BufMut>(&self, out: &mut B) {
                out.put_slice(&(*self as $wide).to_be_bytes());
            }
            #[inline]
            fn encoded_len(&self) -> usize {
                4
            }
        }
    };
}

xdr_widened!(u8, u32);
xdr_widened!(i8, i32);
xdr_widened!(u16, u32);
xdr_widened!(i16, i32);
// 16-bit integers are never packed, so arrays of them are ordinary XDR arrays.
impl XdrElement for u16 {}
impl XdrElement for i16 {}

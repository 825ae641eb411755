//! XDR primitives exactly as Player's generated packers apply them.
//!
//! Player serialises every C struct member in declaration order with one standard XDR
//! routine. The rules that matter (and that break implementations most often):
//!
//! * every 8- and 16-bit integer is widened to 4 bytes on the wire;
//! * a variable array carries its count twice: the `x_count` member, then XDR's own length
//!   prefix ([`Vec<T>`] and [`Opaque`] read and write both);
//! * byte arrays are packed one byte per element and zero-padded to a multiple of 4
//!   ([`Opaque`], [`PlayerString`]); all other arrays use 4 or 8 bytes per element;
//! * fixed arrays (`double cov[6]`) carry no length at all (`[T; N]`).
//!
//! Decoding goes through `nom` on a borrowed body slice. The `body` handle passed alongside
//! lets byte arrays (camera frames, map tiles) be returned as zero-copy slices of the
//! received buffer instead of copies.

pub use super::xdr_bytes::{
    FixedBytes, decode_counted_bytes, decode_packed_bytes, encode_counted_bytes,
    encode_packed_bytes, pad4,
};
pub use super::xdr_codec::{
    Xdr, XdrElement, XdrError, XdrFault, XdrResult, check_max_length, counted_length, decode_all,
    fail, in_field,
};

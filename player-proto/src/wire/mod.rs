//! The wire layer: XDR primitives, header, addresses, banner and framing.

pub mod address;
pub mod banner;
pub mod frame;
pub mod header;
pub mod interface;
#[cfg(feature = "serde")]
mod serde_impls;
pub mod strings;
pub mod xdr;
pub mod xdr_bytes;
mod xdr_codec;
mod xdr_numbers;
pub mod xdr_view;

pub use address::{AddrParseError, DevAddr};
pub use banner::{BANNER_LEN, Banner, BannerError};
pub use frame::{DEFAULT_MAX_BODY, Frame, FrameDecoder, FrameError, RECEIVE_CHUNK};
pub use header::{HEADER_LEN, Header, HeaderError, MessageClass, MsgType};
pub use interface::Interface;
#[cfg(feature = "serde")]
pub use serde_impls::serde_bytes;
pub use strings::{Opaque, PlayerString};
pub use xdr::{FixedBytes, Xdr, XdrElement, XdrError, XdrFault};
pub use xdr_view::{View, XdrArray, XdrView};

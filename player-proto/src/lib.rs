//! The Player 3.x robot-server protocol, written from scratch: XDR over TCP, port 6665.
//!
//! * [`wire`] — XDR primitives as Player applies them, the 40-byte header, device addresses,
//!   the banner, and framing of a byte stream.
//! * [`interfaces`] — one module per Player interface with its typed messages.
//! * [`message`] — a header and a typed body; decoding dispatches on interface code.
//! * [`delivery`] — data modes and replace rules, shared by [`client`] and [`server`].
//! * [`access`] — what an observer may send, for read-only clients and for servers that
//!   let only one client command.
//! * [`robot_id`] — who a robot is (its server, and its name where it has one), said alike
//!   by every front.
//!
//! Decoding never panics and never allocates more than the bytes received justify; encoding
//! writes into any [`bytes::BufMut`]. A message that is only looked at can be read where it
//! lies, with no allocation: every struct has a view ([`wire::xdr_view`]), made through its
//! kind (`Laser::DATA_SCAN.view(&header, &body)`).

#[macro_use]
mod macros;

pub mod access;
pub mod body_kind;
pub mod capture;
pub mod client;
pub mod delivery;
#[doc(hidden)]
pub mod fuzz_input;
pub mod interfaces;
pub mod message;
pub mod recording;
pub mod robot_id;
pub mod server;
pub mod summary;
pub mod transport;
#[doc(hidden)]
pub mod view_disagreement;
pub mod wire;

#[cfg(test)]
mod roundtrip_tests;

pub use message::{Body, DecodeError, Message};
pub use robot_id::RobotId;
pub use wire::{DevAddr, Header, Interface, MsgType};

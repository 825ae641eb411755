//! One module per Player interface: its message structures and its message table.
//!
//! Every module reads like the protocol document's section for that interface: structs declared
//! with `xdr_struct!` in wire order, then `interface_messages!` mapping (class, subtype) to a
//! body type. The [`crate::message::Body`] enum ties them to interface codes.

use bytes::{BufMut, Bytes};

use crate::wire::MessageClass;
use crate::wire::xdr::XdrError;

pub mod blobfinder;
pub mod bumper;
pub mod camera;
pub mod camera_pixels;
pub mod common;
pub mod fiducial;
pub mod graphics2d;
pub mod graphics3d;
pub mod gripper;
pub mod laser;
pub mod log;
pub mod map;
pub mod player;
pub mod position2d;
pub mod power;
pub mod ranger;
pub mod simulation;
pub mod sonar;
pub mod speech;
pub mod universal;

/// The typed messages of one interface.
pub trait MessageSet: Sized {
    /// Decodes a body of the given class and subtype. `None` when the interface defines no
    /// body for that pair (the caller keeps the bytes as an unknown message). On success also
    /// returns how many trailing bytes the structure left unread.
    fn decode(
        class: MessageClass,
        subtype: u8,
        body: &Bytes,
    ) -> Option<Result<(Self, usize), XdrError<'_>>>;

    /// The class this body belongs to.
    fn class(&self) -> MessageClass;

    /// The subtype number it is sent with.
    fn subtype(&self) -> u8;

    fn encode<B: BufMut>(&self, out: &mut B);

    fn encoded_len(&self) -> usize;
}

//! One module per Player interface: its message structures and its message table.
//!
//! Every module reads like the protocol document's section for that interface: structs declared
//! with `xdr_struct!` in wire order, then `interface_messages!` mapping (class, subtype) to a
//! body type. The [`crate::message::Body`] enum ties them to interface codes.
//!
//! # Naming subtypes
//!
//! A subtype number is written once, in its interface's table, beside the name Player gives
//! it without the `PLAYER_<INTERFACE>_` prefix (`Data 1 as DATA_SCAN`). Everything else names
//! the message through what the table generates (see [`kind`]):
//!
//! * `Laser::REQ_GET_GEOM`, a [`kind::BodyKind`]: interface, class, subtype and body type of
//!   one row — send a request with it and read its typed reply;
//! * `LaserScan::KIND`, from [`kind::DataBody`]: the same for a DATA body, so
//!   `latest_of::<LaserScan>()` needs no number;
//! * [`kind::MessageKind::data_of`]: every DATA kind of an interface, for code that takes
//!   whichever the driver sends (a laser's three scan forms, a status line's freshness).
//!
//! The `REQ_*`/`CMD_*` `u8` constants beside some tables are the protocol's names for rows
//! that have no body here (`REQ_DATA`, `CMD_CLEAR`) or for the server side's match arms; a
//! test checks that they agree with the tables.

use bytes::{BufMut, Bytes};

use crate::message::{DecodeError, Message};
use crate::wire::{Header, MessageClass};

pub mod blobfinder;
pub mod bumper;
pub mod camera;
pub mod camera_pixels;
pub mod common;
pub mod fiducial;
pub mod graphics2d;
pub mod graphics3d;
pub mod gripper;
pub mod ir;
pub mod kind;
pub mod laser;
pub mod localize;
pub mod log;
pub mod map;
pub mod planner;
pub mod player;
pub mod pointcloud3d;
pub mod position2d;
pub mod power;
pub mod ptz;
pub mod ranger;
pub mod simulation;
pub mod sonar;
pub mod speech;
pub mod speech_recognition;
pub mod universal;

/// The typed messages of one interface.
pub trait MessageSet: Sized {
    /// Decodes the body of a message of this interface, class and subtype from `header`,
    /// into the whole message: a body the interface defines no structure for is kept as
    /// [`Body::Unknown`](crate::message::Body::Unknown), bytes left after the structure as
    /// the message's `trailing`.
    ///
    /// It returns the finished [`Message`] rather than the body because a laser scan is
    /// decoded every few microseconds: built here, in the place it is returned to, the value
    /// is not moved again through a body, an optional result and a message (a 181-beam scan
    /// spent more time in those moves than in converting its ranges).
    fn decode_message(header: Header, body: Bytes) -> Result<Message, DecodeError>;

    /// Whether viewing `body` in place agrees with decoding it (see [`crate::wire::xdr_view`]);
    /// for the tests and the fuzz target.
    #[doc(hidden)]
    fn view_agrees(header: &Header, body: &Bytes) -> Result<(), String>;

    /// The class this body belongs to.
    fn class(&self) -> MessageClass;

    /// The subtype number it is sent with.
    fn subtype(&self) -> u8;

    fn encode<B: BufMut>(&self, out: &mut B);

    fn encoded_len(&self) -> usize;
}

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

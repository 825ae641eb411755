//! The pv3d component model: what a component (a plugin) is and what it works with. Read this
//! crate to write a component; the standard components live in the `plugins` crate and the
//! application that composes and draws them in `pv3d`.
//!
//! * [`plugin`] — the [`Plugin`] trait (its lifecycle: initialize, run, clean), its
//!   [`PluginContext`], input events and services.
//! * [`registry`] — the components by library name, each with its [`Metadata`] (author,
//!   e-mail, web page, description).
//! * [`scene`] — the tree of [`scene::Object3D`] plugins fill and the viewer draws (no OpenGL
//!   here: a plugin describes geometry, `pv3d` renders it).
//! * [`config`] — plugin parameters with defaults and errors that say where.
//! * [`device`] — what a plugin sees of its Player device.
//! * [`query`] — components asking one another in XML ("go to", "which zone"), and
//!   the world's own answers ("is there any person").
//! * [`action`] — what a robot can do with a clicked object (go to, follow).
//! * [`parent_link`] — hanging a sensor below its robot's node.
//! * [`skin`] — shared OBJ meshes that replace a robot's box.
//! * [`testing`] — a scene, anchors and a hand-fed device, to test a plugin without a server.

pub mod action;
pub mod config;
pub mod device;
pub mod parent_link;
pub mod plugin;
pub mod query;
pub mod registry;
pub mod scene;
pub mod skin;
pub mod testing;

pub use action::{Action, ObjectRef};
pub use config::{ConfigValueError, Param, PluginConfig};
pub use device::{Awaited, DeviceAccess, LastTaken};
pub use plugin::{Handled, InputEvent, Plugin, PluginContext};
pub use registry::{Metadata, PluginRegistry};

//! Simulates robots in a Stage world and serves them over the Player protocol.
//!
//! * [`served`] — which devices each robot exposes on which port (from the .cfg).
//! * [`mapfile`] — maps read from images as Player's `mapfile` driver reads them.
//! * [`nav`] — Player's navigation drivers: localization (`amcl`, `fakelocalize`) and the
//!   `wavefront` planner that drives a robot.
//! * [`devices`], [`camera_frames`], [`serve`] — the simulation served over the Player protocol,
//!   stepped by `stepper` at its pace or in lockstep with its clients.
//! * [`sim_record`] — the simulation's own recording, stamped with simulated time.
//! * [`replay`] — a recording served as the Player servers it was recorded from.
//! * [`speech`] — speech heard from a file or standard input, and said into a log and WAV files.
//! * [`sim`] — the simulation: motion, collisions, sensors by ray casting.
//! * [`world`] — the world a file describes: floorplan, robots and their sensors, obstacles.
//! * [`worldfile`] — the syntax of Stage world files and Player config files.
//!
//! The layers depend one way, from what serves down to what is simulated: `serve` → `devices`
//! → `served` → `camera_frames` → `nav` → `sim` → `world` → `worldfile`. The simulation knows
//! nothing of Player's devices or drivers: it steps the navigation drivers as its
//! [`sim::Drivers`], which `nav` implements.

pub mod camera_frames;
pub mod devices;
pub mod image_file;
pub mod mapfile;
pub mod nav;
pub mod replay;
pub mod serve;
pub mod serve_options;
pub mod served;
pub mod sim;
pub mod sim_record;
pub mod speech;
mod stepper;
pub use serve_options::StepObserver;
pub mod world;
pub mod worldfile;

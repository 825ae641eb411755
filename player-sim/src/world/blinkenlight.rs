//! A blinkenlight on a robot as Stage 4.3 has it: not only a light but a body. Stage gives
//! every model a box for a block (most sensor models clear theirs; the blinkenlight keeps it,
//! 2 cm each way unless its `size` says otherwise), standing on what it is mounted on, and
//! draws it into its raster like any other block.
//!
//! Rangers at its height meet it, and at any height its cells make their region one Stage's
//! rays walk cell by cell rather than jump: a laser passing the robot's own light steps on
//! from where it was, rather than starting again where its line leaves the region, and its
//! stepped path (and so which table leg it grazes) is Stage's. In uoa_robotics_lab, at one of
//! the golden poses, the robot's lights alone hold a region its laser crosses: without them 18
//! laser beams and a sonar's took another path through the tables' legs, some over 3 m off
//! Stage's readings.

use super::models::Model;

/// Stage's blinkenlight size when the world file gives none, m.
const SIZE: [f64; 3] = [0.02; 3];

/// Is `child` a blinkenlight?
pub(super) fn is_blinkenlight(child: &Model) -> bool {
    child.kind == "blinkenlight"
}

/// The size a mounted model has when it sets none: a blinkenlight's own, else none.
pub(super) fn default_size(child: &Model) -> [f64; 3] {
    if is_blinkenlight(child) {
        SIZE
    } else {
        [0.0; 3]
    }
}

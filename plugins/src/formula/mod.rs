//! LaTeX math in the world ([`typeset`]), and `libpv3d_formula`: a formula label that follows
//! its robot, for the classroom.
pub mod typeset;

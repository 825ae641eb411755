//! Grades a class of robot programs: each student's program runs against its own seeded,
//! lockstep simulation of the teacher's world, in a sandbox, and is scored by the teacher's
//! checks; each run is recorded, drawn and reported (see docs/GRADING.md).
//!
//! * [`spec`] — the teacher's spec (TOML), every mistake named by file, line and field.
//! * [`run`] — one program against one simulation, in its [`sandbox`], ended by the time
//!   limit, by itself or by the wall-clock cap; its [`output`] kept bounded; its [`trace`].
//! * [`checks`] — the teacher's rules judged on the trace; [`python_check`] for the rest.
//! * [`grade`] — one submission graded into its folder; [`picture`] draws its path.
//! * [`class`] — a class graded on every core; [`report`] writes what people and tools read.

pub mod checks;
pub mod class;
pub mod grade;
pub mod graded;
pub mod output;
pub mod picture;
pub mod python_check;
pub mod report;
pub mod run;
pub mod sandbox;
pub mod spec;
pub mod trace;
pub mod zone;

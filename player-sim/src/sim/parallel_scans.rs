//! The scans a step's controllers read, cast on several threads: each scan reads only the world
//! as the step found it (no robot moves until every controller has decided), so the scans are
//! independent and the run is the same, bit for bit, on any number of threads. With 100
//! wandering robots the scans are nearly all of a step; two cores nearly halve it.
//!
//! `std::thread::scope`, not a pool crate: the work is one even split per step (robots in
//! contiguous runs, one run per thread), borrowing the simulation for the scope's length, which
//! the standard library's scoped threads give without `'static` copies or a dependency; a
//! thread's start (tens of microseconds) is small against a step of a hundred scans.

use std::num::NonZeroUsize;

use super::{Simulation, ranger_scan};

/// Fewer scans than this in a step are cast on the caller's thread alone: a thread's start
/// would cost more than it saves.
const SCANS_PER_THREAD: usize = 16;

/// The most threads a simulation takes by default.
const DEFAULT_MOST: usize = 8;

/// Threads a new simulation may use: the machine's cores, at most [`DEFAULT_MOST`].
pub fn default_threads() -> usize {
    std::thread::available_parallelism()
        .map_or(1, NonZeroUsize::get)
        .min(DEFAULT_MOST)
}

impl Simulation {
    /// The ranges of each `(robot, ranger)` of `which`, in order, on up to the simulation's
    /// threads.
    pub(super) fn scans_of(&self, which: &[(usize, usize)]) -> Vec<Vec<f64>> {
        let scan = |&(robot, ranger): &(usize, usize)| {
            ranger_scan(self, robot, &self.world.robots[robot].rangers[ranger])
        };
        let threads = self.threads.min(which.len() / SCANS_PER_THREAD).max(1);
        self.sensing(|_| {
            if threads == 1 {
                return which.iter().map(scan).collect();
            }
            let per_thread = which.len().div_ceil(threads);
            std::thread::scope(|scope| {
                let mut runs = which.chunks(per_thread);
                // The caller's thread takes the first run itself.
                let first = runs.next().unwrap_or_default();
                let others: Vec<_> = runs
                    .map(|run| scope.spawn(move || run.iter().map(scan).collect::<Vec<_>>()))
                    .collect();
                let mut all: Vec<Vec<f64>> = first.iter().map(scan).collect();
                for other in others {
                    all.extend(other.join().expect("a scan thread"));
                }
                all
            })
        })
    }
}

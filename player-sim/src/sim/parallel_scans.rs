//! The scans a step's controllers read, cast on several threads: each scan reads only the world
//! as the step found it (no robot moves until every controller has decided), so the scans are
//! independent and the run is the same, bit for bit, on any number of threads. With 100
//! wandering robots the scans are nearly all of a step; two cores nearly halve it.
//!
//! `std::thread::scope`, not a pool crate: the work is split per step into short runs of
//! robots that the threads take in turn (results put back in order), borrowing the simulation
//! for the scope's length, which the standard library's scoped threads give without `'static`
//! copies or a dependency; a thread's start (tens of microseconds) is small against a step of
//! a hundred scans.

use std::num::NonZeroUsize;
use std::sync::atomic::{AtomicUsize, Ordering};

use super::{Simulation, ranger_scan};

/// Fewer scans than this in a step are cast on the caller's thread alone: a thread's start
/// would cost more than it saves.
const SCANS_PER_THREAD: usize = 16;

/// Scans a thread takes at a time: neighbouring robots, whose scans read the same walls.
const RUN: usize = 16;

/// The most threads a simulation takes by default.
const DEFAULT_MOST: usize = 8;

/// Threads a new simulation may use: the machine's cores, at most [`DEFAULT_MOST`].
pub fn default_threads() -> usize {
    std::thread::available_parallelism()
        .map_or(1, NonZeroUsize::get)
        .min(DEFAULT_MOST)
}

impl Simulation {
    /// What `read` makes of the ranges of each `(robot, ranger)` of `which`, in order, on up
    /// to the simulation's threads: each scan is read on the thread that cast it, so that only
    /// what the caller needs of it comes back to the step's own thread.
    pub(super) fn scans_of<T: Send>(
        &self,
        which: &[(usize, usize)],
        read: impl Fn(&[f64]) -> T + Sync,
    ) -> Vec<T> {
        let scan = |&(robot, ranger): &(usize, usize)| {
            read(&ranger_scan(
                self,
                robot,
                &self.world.robots[robot].rangers[ranger],
            ))
        };
        let threads = self.threads.min(which.len() / SCANS_PER_THREAD).max(1);
        self.sensing(|_| {
            if threads == 1 {
                return which.iter().map(scan).collect();
            }
            // Runs of a few neighbouring robots, taken in turn by whichever thread is free: a
            // thread whose robots stand near walls (walked beams) no longer keeps the other
            // waiting, as one fixed half each did in the swarm.
            let runs: Vec<&[(usize, usize)]> = which.chunks(RUN).collect();
            let next = AtomicUsize::new(0);
            let take = || {
                let mut done = Vec::new();
                loop {
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    let Some(run) = runs.get(k) else {
                        return done;
                    };
                    done.push((k, run.iter().map(scan).collect::<Vec<_>>()));
                }
            };
            let mut done = std::thread::scope(|scope| {
                let others: Vec<_> = (1..threads).map(|_| scope.spawn(take)).collect();
                // The caller's thread takes runs too.
                let mut done = take();
                for other in others {
                    done.extend(other.join().expect("a scan thread"));
                }
                done
            });
            done.sort_unstable_by_key(|&(k, _)| k);
            done.into_iter().flat_map(|(_, scans)| scans).collect()
        })
    }
}

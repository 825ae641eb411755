//! Lockstep: a simulation that advances one step once every client driving a robot has sent
//! its command for the step, so that a run depends on what the programs decide and not on
//! how fast the machine lets them decide it.
//!
//! A **driver** is a connection that has sent a command to a device. Each step waits until
//! every present driver has sent a command since the previous step (or until
//! [`Lockstep::release`] lets steps go without them). A driver whose command does not come
//! within the patience is marked absent — the step goes on without it, with one log line —
//! until it commands again. With no present driver at all (none yet, or all gone), the
//! step waits the same patience for one to appear — counted again from each connection that
//! opens meanwhile — then the simulation runs on its own until one does.
//!
//! A driver's second command in one step waits (its session awaits [`Lockstep::turn`]) until
//! the step it answered has been taken: otherwise the command would land before or after the
//! step as the scheduler pleased.

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Condvar, Mutex, MutexGuard};
use std::time::{Duration, Instant};

use tokio::sync::watch;

/// How long the stepper sleeps at most between looks at its stop flag.
const STOP_CHECK: Duration = Duration::from_millis(50);

/// Where a driver stands in the current step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Turn {
    /// The step waits for its command.
    Pending,
    /// It sent its command for this step.
    Answered,
    /// It missed a step's patience: not waited for until it commands again.
    Absent,
    /// It answered, then its connection closed: its answer still counts for this step, which
    /// is taken as if it had stayed, and then it is forgotten.
    Gone,
}

#[derive(Debug)]
struct Turns {
    /// Steps taken so far.
    step: u64,
    /// Whether any connection has commanded.
    ever_driven: bool,
    /// By connection ([`super::Peer::id`]).
    drivers: BTreeMap<u64, Turn>,
    /// Steps that may go without waiting for anyone ([`Lockstep::release`]).
    released: u64,
    /// Since when the step has been waiting (for the patience).
    waiting_since: Instant,
    /// The simulation runs on its own: no driver present, and the patience for one passed.
    running_alone: bool,
    /// The stepper is waiting in [`Lockstep::next_step`].
    stepper_waiting: bool,
}

impl Turns {
    /// Drivers not absent: how many, and how many of them answered.
    fn present(&self) -> (usize, usize) {
        self.drivers
            .values()
            .fold((0, 0), |(present, answered), turn| match turn {
                Turn::Absent => (present, answered),
                Turn::Answered | Turn::Gone => (present + 1, answered + 1),
                Turn::Pending => (present + 1, answered),
            })
    }
}

/// Why the stepper may take a step ([`Lockstep::next_step`]).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum StepCause {
    /// Every present driver sent its command.
    Answered,
    /// A step was released (`world.step()`).
    Released,
    /// Drivers that did not answer within the patience, now absent (connection ids).
    Late(Vec<u64>),
    /// No driver is present.
    Alone,
}

/// The shared turnstile of a lockstep simulation: sessions report commands and departures,
/// the stepper waits for its turn.
#[derive(Debug)]
pub struct Lockstep {
    /// `None`: wait for drivers for ever.
    patience: Option<Duration>,
    turns: Mutex<Turns>,
    changed: Condvar,
    steps: watch::Sender<u64>,
}

impl Lockstep {
    /// A turnstile that waits at most `patience` (wall clock) for a driver's command.
    pub fn new(patience: Option<Duration>) -> Lockstep {
        Lockstep {
            patience,
            turns: Mutex::new(Turns {
                step: 0,
                ever_driven: false,
                drivers: BTreeMap::new(),
                released: 0,
                waiting_since: Instant::now(),
                running_alone: false,
                stepper_waiting: false,
            }),
            changed: Condvar::new(),
            steps: watch::channel(0).0,
        }
    }

    fn lock(&self) -> MutexGuard<'_, Turns> {
        self.turns.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Steps taken so far.
    pub fn steps(&self) -> u64 {
        self.lock().step
    }

    /// Whether any connection has commanded since the simulation started.
    pub fn ever_driven(&self) -> bool {
        self.lock().ever_driven
    }

    /// Waits (asynchronously) until connection `peer` may command: at once, unless it already
    /// answered the step being waited for, in which case until that step has been taken.
    pub async fn turn(&self, peer: u64) {
        let mut taken = self.steps.subscribe();
        loop {
            let waiting_on = {
                let turns = self.lock();
                match turns.drivers.get(&peer) {
                    Some(Turn::Answered) => turns.step,
                    _ => return,
                }
            };
            if taken.wait_for(|&s| s > waiting_on).await.is_err() {
                return;
            }
        }
    }

    /// Connection `peer` sent a command: it is a driver, and it has answered this step.
    pub fn commanded(&self, peer: u64) {
        let mut turns = self.lock();
        turns.drivers.insert(peer, Turn::Answered);
        turns.ever_driven = true;
        if turns.running_alone {
            turns.running_alone = false;
            tracing::info!("lockstep: a driver arrived; each step waits for its command");
        }
        drop(turns);
        self.changed.notify_all();
    }

    /// A connection opened. While nobody drives, it may be the driver the world waits for: the
    /// wait for a first command starts again (and a world running alone stops to wait), so a
    /// program that took long to start still has the whole patience for its first command.
    pub fn arrived(&self) {
        let mut turns = self.lock();
        if turns.present().0 == 0 {
            turns.waiting_since = Instant::now();
            turns.running_alone = false;
        }
        drop(turns);
        self.changed.notify_all();
    }

    /// Connection `peer` closed: the steps stop waiting for it (a command it sent for this
    /// step still counts for it).
    pub fn left(&self, peer: u64) {
        let mut turns = self.lock();
        match turns.drivers.get(&peer) {
            Some(Turn::Answered) => {
                turns.drivers.insert(peer, Turn::Gone);
            }
            Some(_) => {
                turns.drivers.remove(&peer);
                if turns.present().0 == 0 {
                    turns.waiting_since = Instant::now();
                }
            }
            None => {}
        }
        drop(turns);
        self.changed.notify_all();
    }

    /// Whether every driver's connection has closed and every step they answered has been
    /// taken, the stepper waiting for the next: a run ended by its program's end ends here, at
    /// the same step every time.
    pub fn settled(&self) -> bool {
        let turns = self.lock();
        turns.drivers.is_empty() && turns.stepper_waiting && turns.released == 0
    }

    /// Lets `steps` more steps go without waiting for anyone.
    pub fn release(&self, steps: u64) {
        self.lock().released += steps;
        self.changed.notify_all();
    }

    /// Blocks the stepper until the next step may be taken, or `stop` is set (then `None`).
    /// The caller takes the step, then calls [`Self::stepped`].
    pub fn next_step(&self, stop: &AtomicBool) -> Option<StepCause> {
        let mut turns = self.lock();
        turns.stepper_waiting = true;
        let cause = loop {
            if stop.load(Ordering::Relaxed) {
                break None;
            }
            if turns.released > 0 {
                turns.released -= 1;
                break Some(StepCause::Released);
            }
            let (present, answered) = turns.present();
            if present > 0 {
                if answered == present {
                    break Some(StepCause::Answered);
                }
            } else if turns.running_alone {
                break Some(StepCause::Alone);
            }
            let waited = turns.waiting_since.elapsed();
            if let Some(patience) = self.patience
                && waited >= patience
            {
                break Some(self.give_up_waiting(&mut turns));
            }
            let nap = self
                .patience
                .map_or(STOP_CHECK, |p| p.saturating_sub(waited).min(STOP_CHECK));
            turns = self
                .changed
                .wait_timeout(turns, nap)
                .unwrap_or_else(|e| e.into_inner())
                .0;
        };
        turns.stepper_waiting = false;
        cause
    }

    /// The patience ran out: whoever is pending is absent from now on.
    fn give_up_waiting(&self, turns: &mut Turns) -> StepCause {
        let late: Vec<u64> = turns
            .drivers
            .iter()
            .filter(|(_, t)| **t == Turn::Pending)
            .map(|(&id, _)| id)
            .collect();
        if late.is_empty() {
            turns.running_alone = true;
            tracing::info!(
                "lockstep: no client has commanded for {:.1} s; the simulation runs on its own \
                 until one does",
                self.patience.unwrap_or_default().as_secs_f64()
            );
            return StepCause::Alone;
        }
        for id in &late {
            turns.drivers.insert(*id, Turn::Absent);
        }
        turns.running_alone = turns.present().0 == 0;
        tracing::warn!(
            "lockstep: {} client(s) sent no command within {:.1} s; going on without them until \
             they command again",
            late.len(),
            self.patience.unwrap_or_default().as_secs_f64()
        );
        StepCause::Late(late)
    }

    /// The step was taken: present drivers owe the next one, and commands held back go.
    pub fn stepped(&self) {
        let step = {
            let mut turns = self.lock();
            turns.step += 1;
            turns.drivers.retain(|_, turn| *turn != Turn::Gone);
            for turn in turns.drivers.values_mut() {
                if *turn == Turn::Answered {
                    *turn = Turn::Pending;
                }
            }
            turns.waiting_since = Instant::now();
            turns.step
        };
        self.steps.send_replace(step);
        self.changed.notify_all();
    }

    /// Blocks until at least `step` steps have been taken, at most `limit`; whether they were.
    pub fn wait_for_step(&self, step: u64, limit: Duration) -> bool {
        let deadline = Instant::now() + limit;
        let mut turns = self.lock();
        while turns.step < step {
            let Some(left) = deadline.checked_duration_since(Instant::now()) else {
                return false;
            };
            turns = self
                .changed
                .wait_timeout(turns, left)
                .unwrap_or_else(|e| e.into_inner())
                .0;
        }
        true
    }
}

#[cfg(test)]
mod tests;

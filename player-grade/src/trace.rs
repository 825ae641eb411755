//! What a run did, as the simulation knew it: the true pose of every robot at every step, and
//! the graded robot's stall flag and speed. The checks read it; so do a teacher's Python
//! checks (as JSON) and the picture of the run.

use std::sync::{Arc, Mutex};

use player_sim::StepObserver;
use player_sim::sim::Simulation;
use serde::Serialize;

use crate::zone::Zone;

/// One step.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sample {
    /// Simulated seconds.
    pub time: f64,
    /// Every robot's (x, y, yaw), world frame.
    pub poses: Vec<(f64, f64, f64)>,
    /// The graded robot's base reports a stall.
    pub stall: bool,
    /// The graded robot's speed over the floor, m/s.
    pub speed: f64,
}

/// A run, step by step.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Trace {
    /// The graded robot's index among `names`.
    pub robot: usize,
    pub names: Vec<String>,
    /// Simulated seconds per step.
    pub interval: f64,
    pub samples: Vec<Sample>,
}

impl Trace {
    pub fn new(robot: usize, names: Vec<String>, interval: f64) -> Trace {
        Trace {
            robot,
            names,
            interval,
            samples: Vec::new(),
        }
    }

    /// The sample of the simulation as it is now.
    pub fn sample(sim: &Simulation, robot: usize) -> Sample {
        let state = &sim.robots[robot];
        Sample {
            time: sim.time,
            poses: sim
                .robots
                .iter()
                .map(|r| (r.pose.x, r.pose.y, r.pose.a))
                .collect(),
            stall: state.stall,
            speed: state.velocity.0.hypot(state.velocity.1),
        }
    }

    /// A trace of `sim`'s robot `robot`, starting with the world as it is, and the observer
    /// that adds each step to it.
    pub fn observe(sim: &Simulation, robot: usize) -> (Arc<Mutex<Trace>>, StepObserver) {
        let names = sim.world.robots.iter().map(|r| r.name.clone()).collect();
        let mut trace = Trace::new(robot, names, sim.world.interval);
        trace.samples.push(Trace::sample(sim, robot));
        let trace = Arc::new(Mutex::new(trace));
        let observer = {
            let trace = trace.clone();
            StepObserver(Arc::new(move |sim: &Simulation| {
                let sample = Trace::sample(sim, robot);
                trace
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .samples
                    .push(sample);
            }))
        };
        (trace, observer)
    }

    /// The graded robot's path: (time, x, y).
    pub fn path(&self) -> impl Iterator<Item = (f64, f64, f64)> + '_ {
        self.samples.iter().map(|s| {
            let (x, y, _) = s.poses[self.robot];
            (s.time, x, y)
        })
    }

    /// Simulated seconds the run lasted.
    pub fn duration(&self) -> f64 {
        self.samples.last().map_or(0.0, |s| s.time)
    }

    /// Where the graded robot ended.
    pub fn end(&self) -> (f64, f64) {
        self.path().last().map_or((0.0, 0.0), |(_, x, y)| (x, y))
    }

    pub fn end_speed(&self) -> f64 {
        self.samples.last().map_or(0.0, |s| s.speed)
    }

    /// When and where the graded robot was first inside `zone`.
    pub fn first_inside(&self, zone: &Zone) -> Option<(f64, f64, f64)> {
        self.path().find(|&(_, x, y)| zone.contains(x, y))
    }

    /// When and where the graded robot first stalled.
    pub fn first_stall(&self) -> Option<(f64, f64, f64)> {
        self.samples
            .iter()
            .zip(self.path())
            .find(|(s, _)| s.stall)
            .map(|(_, p)| p)
    }

    /// Metres the graded robot travelled.
    pub fn travelled(&self) -> f64 {
        let path: Vec<(f64, f64)> = self.path().map(|(_, x, y)| (x, y)).collect();
        path.windows(2)
            .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
            .sum()
    }

    /// The share of the steps in which the graded robot was within `distance` of `other`.
    pub fn share_within(&self, other: usize, distance: f64) -> f64 {
        if self.samples.is_empty() {
            return 0.0;
        }
        let close = self
            .samples
            .iter()
            .filter(|s| {
                let (a, b) = (s.poses[self.robot], s.poses[other]);
                (a.0 - b.0).hypot(a.1 - b.1) <= distance
            })
            .count();
        close as f64 / self.samples.len() as f64
    }
}

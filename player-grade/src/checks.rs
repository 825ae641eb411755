//! The teacher's rules and how a run is scored by them: each check looks at the trace (the
//! true poses of every step) and gives its points or none, saying why.

use std::path::PathBuf;

use serde::Serialize;

use crate::trace::Trace;
use crate::zone::Zone;

/// What a check asks of the run.
#[derive(Debug, Clone, PartialEq)]
pub enum Rule {
    /// Ever inside the zone (before `within` simulated seconds, if given).
    Reach { zone: Zone, within: Option<f64> },
    /// The base never reports a stall.
    NoStall,
    /// Inside the zone when the run ends.
    EndIn(Zone),
    /// Never inside the zone.
    Avoid(Zone),
    /// At least `min` metres travelled.
    Distance { min: f64 },
    /// Slower than `speed` m/s when the run ends.
    StopAtEnd { speed: f64 },
    /// Within `distance` of robot `target` for at least `share` of the run.
    Follow {
        target: usize,
        target_name: String,
        distance: f64,
        share: f64,
    },
    /// A function of the teacher's, given the run, returns the share of the points.
    Python { file: PathBuf, function: String },
}

/// One check of a spec.
#[derive(Debug, Clone, PartialEq)]
pub struct Check {
    pub name: String,
    pub points: f64,
    pub rule: Rule,
}

/// A check's verdict.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Verdict {
    pub name: String,
    pub score: f64,
    pub max_score: f64,
    /// Why, in a sentence.
    pub output: String,
}

impl Verdict {
    pub fn passed(&self) -> bool {
        self.score >= self.max_score
    }
}

impl Check {
    /// This check's verdict on `trace`, or `None` for a Python check (run elsewhere).
    pub fn judge(&self, trace: &Trace) -> Option<Verdict> {
        let (share, output) = match &self.rule {
            Rule::Reach { zone, within } => reach(trace, zone, *within),
            Rule::NoStall => match trace.first_stall() {
                Some((t, x, y)) => (0.0, format!("stalled at {t:.1} s at ({x:.2}, {y:.2})")),
                None => (1.0, "never stalled".into()),
            },
            Rule::EndIn(zone) => {
                let (x, y) = trace.end();
                if zone.contains(x, y) {
                    (1.0, format!("ended inside, at ({x:.2}, {y:.2})"))
                } else {
                    let off = zone.distance(x, y);
                    (
                        0.0,
                        format!("ended at ({x:.2}, {y:.2}), {off:.2} m outside"),
                    )
                }
            }
            Rule::Avoid(zone) => match trace.first_inside(zone) {
                Some((t, x, y)) => (0.0, format!("entered at {t:.1} s at ({x:.2}, {y:.2})")),
                None => (1.0, "never entered".into()),
            },
            Rule::Distance { min } => {
                let travelled = trace.travelled();
                let share = if travelled >= *min { 1.0 } else { 0.0 };
                (
                    share,
                    format!("travelled {travelled:.2} m (at least {min} m asked)"),
                )
            }
            Rule::StopAtEnd { speed } => {
                let end = trace.end_speed();
                let share = if end <= *speed { 1.0 } else { 0.0 };
                (
                    share,
                    format!("{end:.3} m/s at the end (at most {speed} asked)"),
                )
            }
            Rule::Follow {
                target,
                target_name,
                distance,
                share,
            } => {
                let close = trace.share_within(*target, *distance);
                let pass = if close >= *share { 1.0 } else { 0.0 };
                let out = format!(
                    "within {distance} m of {target_name} for {:.0} % of the run ({:.0} % asked)",
                    100.0 * close,
                    100.0 * share
                );
                (pass, out)
            }
            Rule::Python { .. } => return None,
        };
        Some(self.verdict(share, output))
    }

    /// The verdict for `share` of the points.
    pub fn verdict(&self, share: f64, output: String) -> Verdict {
        let share = if share.is_finite() {
            share.clamp(0.0, 1.0)
        } else {
            0.0
        };
        Verdict {
            name: self.name.clone(),
            score: self.points * share,
            max_score: self.points,
            output,
        }
    }
}

fn reach(trace: &Trace, zone: &Zone, within: Option<f64>) -> (f64, String) {
    let limit = within.unwrap_or(f64::INFINITY);
    match trace.first_inside(zone) {
        Some((t, _, _)) if t <= limit => (1.0, format!("reached at {t:.1} s")),
        Some((t, _, _)) => (
            0.0,
            format!("reached at {t:.1} s, after the {limit} s asked"),
        ),
        None => {
            let closest = trace
                .path()
                .map(|(_, x, y)| zone.distance(x, y))
                .fold(f64::INFINITY, f64::min);
            (
                0.0,
                format!("never reached: {closest:.2} m away at the closest"),
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::Sample;

    fn straight_run() -> Trace {
        let mut trace = Trace::new(0, vec!["r0".into(), "r1".into()], 0.1);
        for i in 0..=20 {
            let x = i as f64 * 0.1;
            trace.samples.push(Sample {
                time: i as f64 * 0.1,
                poses: vec![(x, 0.0, 0.0), (x + 0.5, 0.0, 0.0)],
                stall: i == 15,
                speed: if i < 20 { 1.0 } else { 0.0 },
            });
        }
        trace
    }

    fn check(rule: Rule) -> Verdict {
        Check {
            name: "c".into(),
            points: 10.0,
            rule,
        }
        .judge(&straight_run())
        .unwrap()
    }

    #[test]
    fn each_kind_judges_the_run() {
        let goal = Zone::Circle {
            x: 1.5,
            y: 0.0,
            radius: 0.05,
        };
        let reached = check(Rule::Reach {
            zone: goal.clone(),
            within: None,
        });
        assert_eq!(
            (reached.score, reached.output.as_str()),
            (10.0, "reached at 1.5 s")
        );
        let late = check(Rule::Reach {
            zone: goal.clone(),
            within: Some(1.0),
        });
        assert_eq!(late.score, 0.0, "{}", late.output);
        assert_eq!(check(Rule::NoStall).score, 0.0);
        assert!(check(Rule::NoStall).output.contains("1.5 s"));
        assert_eq!(check(Rule::EndIn(goal.clone())).score, 0.0);
        let end = Zone::Box {
            xmin: 1.9,
            xmax: 2.1,
            ymin: -0.1,
            ymax: 0.1,
        };
        assert_eq!(check(Rule::EndIn(end.clone())).score, 10.0);
        assert_eq!(check(Rule::Avoid(end)).score, 0.0);
        assert_eq!(check(Rule::Distance { min: 1.9 }).score, 10.0);
        assert_eq!(check(Rule::Distance { min: 2.1 }).score, 0.0);
        assert_eq!(check(Rule::StopAtEnd { speed: 0.05 }).score, 10.0);
        let follow = |distance| {
            check(Rule::Follow {
                target: 1,
                target_name: "r1".into(),
                distance,
                share: 0.9,
            })
        };
        assert_eq!(follow(0.6).score, 10.0);
        assert_eq!(follow(0.4).score, 0.0);
    }

    #[test]
    fn zones_measure_from_their_edge() {
        let ring = Zone::Circle {
            x: 0.0,
            y: 0.0,
            radius: 1.0,
        };
        assert_eq!(ring.distance(3.0, 0.0), 2.0);
        assert!(ring.contains(0.5, 0.5));
        let room = Zone::Box {
            xmin: 0.0,
            xmax: 1.0,
            ymin: 0.0,
            ymax: 1.0,
        };
        assert_eq!(room.distance(4.0, 5.0), 5.0);
        assert!(room.contains(1.0, 0.0));
    }
}

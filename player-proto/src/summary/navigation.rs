//! Summaries of the navigation interfaces: a belief, a plan, a pose with its spread.

use crate::interfaces::common::Pose2d;
use crate::interfaces::localize::{Localize, PoseCovariance, cov};
use crate::interfaces::planner::Planner;

use super::pose;

pub(super) fn pose2d(p: &Pose2d) -> String {
    pose(p.px, p.py, p.pa)
}

/// Standard deviations of x, y and yaw: a reader judges a belief by its spread, not by
/// variances in m² and rad².
fn spread(c: &PoseCovariance) -> String {
    let sd = |v: f64| v.max(0.0).sqrt();
    format!(
        "± ({:.3} m, {:.3} m, {:.1}°)",
        sd(c[cov::XX]),
        sd(c[cov::YY]),
        sd(c[cov::AA]).to_degrees()
    )
}

pub(super) fn localize(l: &Localize) -> String {
    match l {
        Localize::Hypotheses(d) => match d.best() {
            Some(best) => format!(
                "{} hypotheses, best {} {} weight {} ({})",
                d.hypoths.len(),
                pose2d(&best.mean),
                spread(&best.cov),
                best.alpha,
                d.share_of(best)
            ),
            None => "no hypotheses".into(),
        },
        Localize::SetPose(p) => format!("set pose {} {}", pose2d(&p.mean), spread(&p.cov)),
        Localize::Particles(p) => format!(
            "{} particles, mean {} variance {:.3e}",
            p.particles.len(),
            pose2d(&p.mean),
            p.variance
        ),
    }
}

pub(super) fn planner(p: &Planner) -> String {
    match p {
        Planner::State(s) if s.is_done() => {
            format!("done at {}, goal {}", pose2d(&s.pos), pose2d(&s.goal))
        }
        Planner::State(s) if s.is_valid() => format!(
            "at {}, waypoint {} of {} {}, goal {}",
            pose2d(&s.pos),
            s.waypoint_idx,
            s.waypoints_count,
            pose2d(&s.waypoint),
            pose2d(&s.goal)
        ),
        Planner::State(s) => format!("no plan, at {}", pose2d(&s.pos)),
        Planner::Goal(c) => format!("go to {}", pose2d(&c.goal)),
        Planner::Start(c) => format!("start from {}", pose2d(&c.goal)),
        Planner::Waypoints(w) => format!(
            "{} waypoints, {:.2} m",
            w.waypoints.len(),
            w.waypoints_distance
        ),
        Planner::Enable(e) => if e.is_on() { "enable" } else { "disable" }.into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interfaces::localize::{LocalizeData, LocalizeHypothesis};
    use crate::interfaces::planner::{PlannerData, PlannerWaypoints};
    use crate::summary::tests::line;

    #[test]
    fn a_belief_reads_as_its_best_hypothesis_and_spread() {
        let weak = LocalizeHypothesis {
            alpha: 0.25,
            ..Default::default()
        };
        let strong = LocalizeHypothesis {
            mean: Pose2d::new(1.0, -2.0, std::f64::consts::FRAC_PI_2),
            cov: [0.01, 0.04, 0.0, 0.0, 0.0, 0.0],
            alpha: 0.75,
        };
        let data = LocalizeData {
            hypoths: vec![weak, strong],
            ..Default::default()
        };
        assert_eq!(
            line("localize:0", Localize::Hypotheses(data)),
            "2 hypotheses, best (1.000, -2.000, 90.0°) ± (0.100 m, 0.200 m, 0.0°) weight 0.75 (75 %)"
        );
    }

    #[test]
    fn a_plan_reads_as_progress_towards_the_goal() {
        let state = PlannerData {
            valid: 1,
            waypoint_idx: 1,
            waypoints_count: 3,
            goal: Pose2d::new(-2.0, 0.5, 0.0),
            ..Default::default()
        };
        assert_eq!(
            line("planner:0", Planner::State(state)),
            "at (0.000, 0.000, 0.0°), waypoint 1 of 3 (0.000, 0.000, 0.0°), goal (-2.000, 0.500, 0.0°)"
        );
        let done = PlannerData { done: 1, ..state };
        assert!(line("planner:0", Planner::State(done)).starts_with("done at"));
        let plan = PlannerWaypoints {
            waypoints_distance: 8.9765,
            waypoints: vec![Pose2d::default(); 3],
        };
        assert_eq!(
            line("planner:0", Planner::Waypoints(plan)),
            "3 waypoints, 8.98 m"
        );
    }
}

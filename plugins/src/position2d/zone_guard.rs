//! Keeping out of the zones a robot avoids while it drives on its own (a goal, "Follow"):
//! now and then it asks the zones manager "which zone" about where it stands and about the
//! point [`LOOKAHEAD`] ahead on its way, and holds still while the way ahead enters an
//! avoided zone it is not already in. A followed person who walks through "keep out" leaves
//! the robot waiting at the edge; it goes on when the person's way leads elsewhere. The robot
//! keeps no copy of the zones — they are places every component shares — and with no zones
//! manager in the composition nobody answers and it drives.

use std::time::{Duration, Instant};

use glam::Vec2;

use framework::query::{Query, QueryError, Reply, Target, XmlElement};

/// Who knows the zones.
pub(super) const ZONES: &str = "libpv3d_zones";
/// How far ahead the way is looked at, m: several times what the robot covers between two
/// looks at full speed (even in a simulation run faster than real time), so it stops before
/// the edge rather than on it.
pub const LOOKAHEAD: f32 = 0.5;
/// How often the guard asks while the robot drives: as often as velocities are sent, two
/// small queries per driving robot; at 0.5 m/s the robot moves 5 cm between looks.
const LOOK_PERIOD: Duration = Duration::from_millis(100);
/// The attribute marking the guard's own queries, and its two values.
const ABOUT: &str = "about";
const HERE: &str = "robot";
const AHEAD: &str = "way ahead";

/// The zones a robot avoids, and what the zones manager last said about its way.
#[derive(Debug, Clone, Default)]
pub struct ZoneGuard {
    avoid: Vec<String>,
    last_look: Option<Instant>,
    /// Avoided zones the robot stands in (it may drive out of them).
    here: Vec<String>,
    /// Avoided zones the point ahead lies in.
    ahead: Vec<String>,
}

impl ZoneGuard {
    /// A guard for the zones named in `avoid_zones` (`|`-separated).
    pub fn new(avoid_zones: &str) -> ZoneGuard {
        ZoneGuard {
            avoid: avoid_zones
                .split('|')
                .map(str::trim)
                .filter(|z| !z.is_empty())
                .map(str::to_string)
                .collect(),
            ..ZoneGuard::default()
        }
    }

    /// Whether the robot keeps out of `zone`.
    pub fn avoids(&self, zone: &str) -> bool {
        self.avoid.iter().any(|a| a == zone)
    }

    /// The queries to send on the way from `robot` towards `aim`, when a look is due.
    pub fn look(&mut self, now: Instant, robot: Vec2, aim: Vec2) -> Vec<Query> {
        let due = self
            .last_look
            .is_none_or(|at| now.saturating_duration_since(at) >= LOOK_PERIOD);
        if self.avoid.is_empty() || !due {
            return Vec::new();
        }
        self.last_look = Some(now);
        let ahead = robot + (aim - robot).clamp_length_max(LOOKAHEAD);
        let ask = |about: &str, at: Vec2| {
            let point = XmlElement::new("point")
                .with_attr("x", at.x)
                .with_attr("y", at.y);
            Query::new(Target::Named(ZONES.into()), "which zone")
                .with_attr(ABOUT, about)
                .with_child(point)
        };
        vec![ask(HERE, robot), ask(AHEAD, ahead)]
    }

    /// Takes the reply to one of the guard's own queries; false for any other query.
    pub fn take_reply(&mut self, query: &Query, result: &Result<Reply, QueryError>) -> bool {
        let about = query.body.attr(ABOUT);
        if !query.is("which zone") || !matches!(about, Some(HERE | AHEAD)) {
            return false;
        }
        // Nobody answering (no zones manager) means nothing is in the way.
        let avoided: Vec<String> = match result {
            Ok(reply) => reply
                .body
                .children
                .iter()
                .filter_map(|z| z.attr("name"))
                .filter(|zone| self.avoids(zone))
                .map(str::to_string)
                .collect(),
            Err(_) => Vec::new(),
        };
        if about == Some(HERE) {
            self.here = avoided;
        } else {
            self.ahead = avoided;
        }
        true
    }

    /// The avoided zone the way ahead enters, if any: the robot holds still while there is one.
    pub fn blocked_by(&self) -> Option<&str> {
        self.ahead
            .iter()
            .find(|zone| !self.here.contains(zone))
            .map(String::as_str)
    }

    /// Forgets what was said about the way: the robot stopped, or its goal changed.
    pub fn clear(&mut self) {
        self.last_look = None;
        self.here.clear();
        self.ahead.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn zones(names: &[&str]) -> Result<Reply, QueryError> {
        let mut body = XmlElement::new("zones");
        for name in names {
            body.children
                .push(XmlElement::new("zone").with_attr("name", *name));
        }
        Ok(Reply::done(body))
    }

    #[test]
    fn the_way_into_an_avoided_zone_blocks_until_it_leads_elsewhere() {
        let mut guard = ZoneGuard::new("keep out | stairs");
        let t0 = Instant::now();
        let asked = guard.look(t0, Vec2::ZERO, Vec2::new(3.0, 0.0));
        assert_eq!(asked.len(), 2);
        let ahead = asked[1].point().unwrap();
        assert!((ahead.0 - f64::from(LOOKAHEAD)).abs() < 1e-6 && ahead.1 == 0.0);
        assert!(guard.take_reply(&asked[0], &zones(&[])));
        assert!(guard.take_reply(&asked[1], &zones(&["keep out", "hall"])));
        assert_eq!(guard.blocked_by(), Some("keep out"));
        // Not again before the period is over.
        assert!(guard.look(t0, Vec2::ZERO, Vec2::Y).is_empty());
        let later = guard.look(t0 + LOOK_PERIOD, Vec2::ZERO, Vec2::Y);
        assert!(guard.take_reply(&later[1], &zones(&["hall"])));
        assert_eq!(guard.blocked_by(), None);
    }

    #[test]
    fn a_robot_already_inside_may_drive_out_and_no_zones_manager_blocks_nothing() {
        let mut guard = ZoneGuard::new("keep out");
        let asked = guard.look(Instant::now(), Vec2::ZERO, Vec2::X);
        guard.take_reply(&asked[0], &zones(&["keep out"]));
        guard.take_reply(&asked[1], &zones(&["keep out"]));
        assert_eq!(guard.blocked_by(), None, "inside already: it may leave");
        let nobody = Err(QueryError::NoSuchComponent {
            name: "which zone".into(),
            to: Target::Named(ZONES.into()),
        });
        guard.take_reply(&asked[0], &nobody);
        assert_eq!(guard.blocked_by(), Some("keep out"));
        guard.take_reply(&asked[1], &nobody);
        assert_eq!(guard.blocked_by(), None);
    }

    #[test]
    fn other_queries_are_not_the_guards_and_an_empty_list_asks_nothing() {
        let mut guard = ZoneGuard::new("keep out");
        let goal = Query::new(Target::Named(ZONES.into()), "which zone");
        assert!(!guard.take_reply(&goal, &zones(&["keep out"])));
        assert!(
            ZoneGuard::new(" ")
                .look(Instant::now(), Vec2::ZERO, Vec2::X)
                .is_empty()
        );
    }
}

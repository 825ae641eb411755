//! Where a robot has been and where it is headed, drawn on the ground: the trail of its last
//! poses, and a cross at each target (the goal it drives to, a target being dragged) with a
//! line from the robot to it.

use std::collections::VecDeque;

use glam::{Vec2, Vec3};

use super::goal::Goal;
use framework::scene::{Geometry, Rgba};

/// Poses closer than this to the last one kept are not kept, m (a robot standing still
/// leaves no trail).
const MIN_STEP: f32 = 0.02;
/// Height of the drawing above the ground, m (keeps it off the ground plane).
const LIFT: f32 = 0.02;

/// The last `capacity` positions at least [`MIN_STEP`] apart.
#[derive(Debug, Clone, Default)]
pub struct Trail {
    points: VecDeque<Vec3>,
    capacity: usize,
}

impl Trail {
    pub fn new(capacity: usize) -> Trail {
        Trail {
            points: VecDeque::new(),
            capacity,
        }
    }

    /// How many positions it keeps at most (the `trailLength` parameter).
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Forgets every position.
    pub fn clear(&mut self) {
        self.points.clear();
    }

    /// Adds `at` unless it is too close to the last position kept; forgets the oldest beyond
    /// the capacity.
    pub fn record(&mut self, at: Vec2) {
        let here = at.extend(LIFT / 2.0);
        if self.capacity == 0
            || self
                .points
                .back()
                .is_some_and(|last| last.distance(here) <= MIN_STEP)
        {
            return;
        }
        self.points.push_back(here);
        while self.points.len() > self.capacity {
            self.points.pop_front();
        }
    }

    /// Replaces `geometry` with the trail in `color` (faded), and a cross at the goal and at
    /// the target being dragged, each joined to the robot at `robot`.
    pub fn draw(
        &self,
        geometry: &mut Geometry,
        color: Rgba,
        robot: Vec2,
        goal: Option<&Goal>,
        dragging: Option<Vec2>,
    ) {
        geometry.clear();
        let faded = color.with_alpha(150);
        let (front, back) = self.points.as_slices();
        let mut previous: Option<Vec3> = None;
        for &p in front.iter().chain(back) {
            if let Some(q) = previous {
                geometry.line(q, p, faded);
            }
            previous = Some(p);
        }
        let here = robot.extend(LIFT);
        let mut cross = |target: Vec2, marker: Rgba| {
            let at = target.extend(LIFT);
            let r = 0.15;
            geometry.line(at - Vec3::X * r, at + Vec3::X * r, marker);
            geometry.line(at - Vec3::Y * r, at + Vec3::Y * r, marker);
            geometry.line(here, at, marker.with_alpha(120));
        };
        match goal {
            Some(Goal::Point(t)) => cross(*t, Rgba::rgb(250, 200, 60)),
            Some(Goal::Follow { last_seen, .. }) => cross(*last_seen, Rgba::rgb(240, 110, 200)),
            None => {}
        }
        if let Some(t) = dragging {
            cross(t, Rgba::rgb(90, 220, 240));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_trail_keeps_the_newest_positions_that_moved() {
        let mut trail = Trail::new(3);
        for x in [0.0, 0.01, 1.0, 2.0, 3.0] {
            trail.record(Vec2::new(x, 0.0));
        }
        let xs: Vec<f32> = trail.points.iter().map(|p| p.x).collect();
        assert_eq!(xs, vec![1.0, 2.0, 3.0], "1 cm is standing still; 3 kept");

        let mut g = Geometry::default();
        trail.draw(&mut g, Rgba::WHITE, Vec2::new(3.0, 0.0), None, None);
        assert_eq!(g.lines.len(), 2 * 2, "two segments through three positions");
        let goal = Goal::Point(Vec2::new(5.0, 5.0));
        trail.draw(&mut g, Rgba::WHITE, Vec2::new(3.0, 0.0), Some(&goal), None);
        assert_eq!(
            g.lines.len(),
            (2 + 3) * 2,
            "and a cross joined to the robot"
        );
    }

    #[test]
    fn no_capacity_no_trail() {
        let mut trail = Trail::new(0);
        trail.record(Vec2::ZERO);
        trail.record(Vec2::ONE);
        assert!(trail.points.is_empty());
    }
}

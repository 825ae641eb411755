//! A pose given by hand on the ground: where the press began is the position, the direction
//! the pointer was dragged is the heading. The localizer's initial pose and the planner's goal
//! are both given this way, so the gesture lives here once.
//!
//! The viewer reports a drag as [`TargetDragged`](framework::InputEvent::TargetDragged) points
//! (the first one where the drag began) and its release as a ground click at the drop point; a
//! plain click, with no drag before it, keeps the heading the caller already had.

use framework::plugin::{Handled, InputEvent};
use glam::Vec2;
use player_proto::interfaces::common::Pose2d;

/// Drags shorter than this, m, give no heading: the hand shook, it did not point.
pub const MIN_HEADING_DRAG: f32 = 0.1;

/// What an input event meant for a plugin that takes a pose by drag ([`PoseDrag::follow`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DragStep {
    /// The plugin became (or stopped being) the active handler.
    Activated(bool),
    /// The pointer moved in a drag: the preview changed.
    Moved,
    /// The gesture ended in this pose: send it.
    Released(Pose2d),
    /// The drag was let go off the ground: the preview is gone.
    Cancelled,
    /// Nothing for the drag.
    Other,
}

impl DragStep {
    /// Whether the plugin's drawing (its preview) changed.
    pub fn redraws(&self) -> bool {
        matches!(
            self,
            DragStep::Moved | DragStep::Released(_) | DragStep::Cancelled
        )
    }

    /// What the plugin answers the viewer: it took the event, or the event goes on.
    pub fn handled(&self) -> Handled {
        match self {
            DragStep::Activated(_) | DragStep::Moved | DragStep::Released(_) => Handled::Yes,
            DragStep::Cancelled | DragStep::Other => Handled::No,
        }
    }
}

/// A pose drag under way.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PoseDrag {
    press: Option<Vec2>,
    pointer: Option<Vec2>,
}

impl PoseDrag {
    /// The pointer is at `point` in a drag: the first point fixes the position.
    pub fn dragged(&mut self, point: Vec2) {
        if self.press.is_none() {
            self.press = Some(point);
        }
        self.pointer = Some(point);
    }

    /// The drag was let go off the ground.
    pub fn cancel(&mut self) {
        *self = PoseDrag::default();
    }

    /// Whether a drag is under way.
    pub fn is_dragging(&self) -> bool {
        self.press.is_some()
    }

    /// The pose the gesture ends in, released (or clicked) at `point`; `heading` when the
    /// gesture gave none (a click, or a drag too short to point).
    pub fn release(&mut self, point: Vec2, heading: f64) -> Pose2d {
        let at = self.press.unwrap_or(point);
        self.cancel();
        let pose = Pose2d::new(f64::from(at.x), f64::from(at.y), heading);
        match heading_of(at, point) {
            Some(pointed) => Pose2d {
                pa: f64::from(pointed),
                ..pose
            },
            None => pose,
        }
    }

    /// Follows the viewer's input for a plugin that takes a pose by drag while it is the
    /// active handler (`active`); a plain click keeps `heading`.
    pub fn follow(&mut self, event: &InputEvent, active: bool, heading: f64) -> DragStep {
        match event {
            InputEvent::Activated(now) => DragStep::Activated(*now),
            InputEvent::TargetDragged(point) if active => {
                self.dragged(point.truncate());
                DragStep::Moved
            }
            InputEvent::GroundClicked(point) if active => {
                DragStep::Released(self.release(point.truncate(), heading))
            }
            InputEvent::TargetDragCancelled => {
                self.cancel();
                DragStep::Cancelled
            }
            _ => DragStep::Other,
        }
    }

    /// What to show while dragging: the position and, once the drag is long enough, the
    /// heading.
    pub fn preview(&self) -> Option<(Vec2, Option<f32>)> {
        let press = self.press?;
        Some((press, self.pointer.and_then(|p| heading_of(press, p))))
    }
}

fn heading_of(from: Vec2, to: Vec2) -> Option<f32> {
    let d = to - from;
    (d.length() >= MIN_HEADING_DRAG).then(|| d.y.atan2(d.x))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn the_press_is_the_position_and_the_drag_the_heading() {
        let mut drag = PoseDrag::default();
        drag.dragged(Vec2::new(1.0, 1.0));
        drag.dragged(Vec2::new(1.0, 1.5));
        assert_eq!(
            drag.preview(),
            Some((Vec2::new(1.0, 1.0), Some(std::f32::consts::FRAC_PI_2)))
        );
        let pose = drag.release(Vec2::new(1.0, 3.0), 0.0);
        assert_eq!((pose.px, pose.py), (1.0, 1.0));
        assert!((pose.pa - FRAC_PI_2).abs() < 1e-6, "{}", pose.pa);
        assert!(!drag.is_dragging(), "released");
    }

    #[test]
    fn a_click_or_a_tiny_drag_keeps_the_heading_given() {
        let mut drag = PoseDrag::default();
        let pose = drag.release(Vec2::new(2.0, -1.0), 0.7);
        assert_eq!((pose.px, pose.py, pose.pa), (2.0, -1.0, 0.7));
        drag.dragged(Vec2::new(0.0, 0.0));
        let pose = drag.release(Vec2::new(0.02, 0.0), -0.3);
        assert_eq!((pose.px, pose.pa), (0.0, -0.3));
        drag.dragged(Vec2::ZERO);
        drag.cancel();
        assert_eq!(drag.preview(), None);
    }
}

//! The chain of responsibility input flows along: the active event handler first, then the
//! clicked object's owner, then the world; selecting, the dragged target, stopping.

use std::time::Instant;

use framework::plugin::{Handled, InputEvent};
use framework::scene::NodeId;

use super::{Viewer, popups};

impl Viewer {
    /// Sends an event to one plugin.
    pub(super) fn send(&mut self, index: usize, event: &InputEvent) -> Handled {
        let (plugin, mut ctx) = self.plugin_in_context(index, Instant::now());
        plugin.on_event(event, &mut ctx)
    }

    /// Tells every plugin to stop (space key, focus lost, quitting).
    pub fn stop_all(&mut self) {
        // An observer has nothing moving to stop, and could not send the stop.
        if self.observing() {
            return;
        }
        for i in 0..self.slots.len() {
            self.send(i, &InputEvent::StopAll);
        }
    }

    /// Makes plugin `index` the active event handler (or none).
    pub fn set_active(&mut self, index: Option<usize>) {
        // An observer drives nothing: no robot becomes the handler of clicks and targets.
        if self.active == index || (index.is_some() && self.observing()) {
            return;
        }
        if let Some(old) = self.active {
            self.send(old, &InputEvent::Activated(false));
        }
        // Actions offered by the robot that was active go with it.
        if matches!(self.popup, Some(popups::Popup::Actions { .. })) {
            self.popup = None;
        }
        self.active = index;
        if let Some(new) = index {
            self.send(new, &InputEvent::Activated(true));
        }
    }

    /// Whether every server is connected and every device in use has sent data (see
    /// [`crate::robots::RobotManager::all_reporting`]); false without servers.
    pub fn every_device_reporting(&self) -> bool {
        self.robots.as_ref().is_some_and(|r| r.all_reporting())
    }

    /// Whether the viewer only observes (`pv3d --observe`).
    pub fn observing(&self) -> bool {
        self.robots.as_ref().is_some_and(|r| r.observing())
    }

    /// The plugin owning a scene node (the node itself or one of its ancestors).
    pub(super) fn owner_of(&self, node: NodeId) -> Option<usize> {
        let mut current = Some(node);
        while let Some(id) = current {
            if let Some(i) = self.slots.iter().position(|s| s.plugin.node() == Some(id)) {
                return Some(i);
            }
            current = self.scene.get(id).and_then(|o| o.parent);
        }
        None
    }

    /// A click in the 3D view, down the chain: active handler, clicked object, world.
    pub fn click(&mut self, picked: Option<NodeId>, ground: Option<glam::Vec3>) {
        // A click elsewhere in the view closes the popup, and only that: a robot is not sent
        // off by the click that dismissed its menu (clicks on the popup never reach the view).
        if self.popup.take().is_some() {
            return;
        }
        let owner = picked.and_then(|n| self.owner_of(n));
        // Clicking another robot selects it.
        if let Some(o) = owner
            && self.active != Some(o)
            && self.slots[o].plugin.can_be_active()
        {
            self.set_active(Some(o));
            return;
        }
        // The active handler's answer to a tagged object: a popup of its actions on it.
        if let Some(node) = picked
            && self.offer_actions(node)
        {
            return;
        }
        let event = match (picked, ground) {
            (Some(node), _) => InputEvent::ObjectClicked(node),
            (None, Some(point)) => InputEvent::GroundClicked(point),
            (None, None) => return,
        };
        if let Some(active) = self.active
            && self.send(active, &event) == Handled::Yes
        {
            return;
        }
        if let Some(o) = owner
            && self.send(o, &event) == Handled::Yes
        {
            return;
        }
        // The world: a click on empty ground deselects.
        if picked.is_none() {
            self.set_active(None);
        }
    }

    /// A secondary click: the active handler's actions on any object, robots included (the
    /// primary click on a robot selects it instead).
    pub fn secondary_click(&mut self, picked: Option<NodeId>) {
        self.popup = None;
        if let Some(node) = picked {
            self.offer_actions(node);
        }
    }

    /// The active handler's target dragged to `point` (shown, not sent yet).
    pub fn drag_target(&mut self, point: glam::Vec3) {
        if let Some(active) = self.active {
            self.send(active, &InputEvent::TargetDragged(point));
        }
    }

    /// The dragged target let go at `point` (sent as a ground click), or off the ground
    /// (forgotten).
    pub fn release_target(&mut self, point: Option<glam::Vec3>) {
        let Some(active) = self.active else { return };
        match point {
            Some(p) => self.send(active, &InputEvent::GroundClicked(p)),
            None => self.send(active, &InputEvent::TargetDragCancelled),
        };
    }

    /// Whether a drag pressed on this ray starts a target drag: it starts on the active robot.
    pub(super) fn starts_on_active(&self, origin: glam::Vec3, dir: glam::Vec3) -> bool {
        let picked = self.scene.pick(origin, dir).map(|(n, _)| n);
        self.active.is_some() && picked.and_then(|n| self.owner_of(n)) == self.active
    }

    /// The title of each plugin, in item-tree order (the index `use_service` takes).
    pub fn titles(&self) -> Vec<String> {
        self.slots.iter().map(|s| s.plugin.title()).collect()
    }

    /// The active event handler's title, if one is active.
    pub fn active_title(&self) -> Option<String> {
        self.active.map(|a| self.slots[a].plugin.title())
    }

    /// Selects the next robot that can be driven (Tab).
    pub fn cycle_active(&mut self) {
        let drivable: Vec<usize> = (0..self.slots.len())
            .filter(|&i| self.slots[i].plugin.can_be_active())
            .collect();
        if drivable.is_empty() {
            return;
        }
        let next = match self
            .active
            .and_then(|a| drivable.iter().position(|&i| i == a))
        {
            Some(p) => drivable[(p + 1) % drivable.len()],
            None => drivable[0],
        };
        self.set_active(Some(next));
    }
}

//! Sentences to the viewer: the command line, a `--script` and speech all end here, parsed
//! with the viewer's grammar against what the scene holds now and carried out by
//! [`crate::commands::executor`]. Each reply (or error) is kept for the command line to show.

use std::time::Instant;

use framework::action::ObjectRef;
use framework::plugin::InputEvent;
use framework::scene::Scene;

use super::Viewer;
use crate::commands::executor::{CommandTarget, execute};
use crate::commands::vocabulary::ROBOT_TAG;
use crate::commands::{Grammar, Script, Vocabulary, parse};

impl Viewer {
    /// Parses and carries out one sentence; the reply says what was done, the error why not.
    pub fn command(&mut self, sentence: &str) -> Result<String, String> {
        let vocabulary = Vocabulary::of_scene(&self.scene);
        let outcome = parse(&self.grammar, &vocabulary, sentence)
            .map_err(|e| e.to_string())
            .and_then(|command| {
                execute(self, &command).map_err(|e| format!("{}: {e}", sentence.trim()))
            });
        match &outcome {
            Ok(reply) => tracing::info!("command {:?}: {reply}", sentence.trim()),
            Err(e) => tracing::warn!("command refused: {e}"),
        }
        match &outcome {
            Ok(reply) => self.say(reply),
            Err(e) => self.say(e),
        }
        self.command_line.show(outcome.clone());
        self.replies.push(outcome.clone());
        outcome
    }

    /// Uses `grammar` for every sentence from now on.
    pub fn set_grammar(&mut self, grammar: Grammar) {
        self.grammar = grammar;
    }

    /// Runs `script` from the next update on, its times counted from then.
    pub fn run_script(&mut self, script: Script) {
        self.script = Some(script);
    }

    /// Every reply and error so far, oldest first (what a speech device says, what tests read).
    pub fn replies(&self) -> &[Result<String, String>] {
        &self.replies
    }

    /// Says the script's lines that are due; an error names the script's file:line.
    pub(super) fn follow_script(&mut self, now: Instant) {
        let Some(script) = self.script.as_mut() else {
            return;
        };
        let due = script.due(now);
        let places: Vec<String> = due.iter().map(|l| script.place(l)).collect();
        for (line, place) in due.iter().zip(places) {
            if let Err(e) = self.command(&line.sentence) {
                let located = format!("{place}: {e}");
                tracing::error!("{located}");
                self.command_line.show(Err(located.clone()));
                if let Some(last) = self.replies.last_mut() {
                    *last = Err(located);
                }
            }
        }
    }

    /// The slot of the drivable robot drawn under `name`.
    fn robot_slot(&self, name: &str) -> Option<usize> {
        self.slots.iter().position(|slot| {
            slot.plugin.can_be_active()
                && slot
                    .plugin
                    .node()
                    .and_then(|n| self.scene.get(n))
                    .is_some_and(|o| o.has_tag(ROBOT_TAG) && o.name == name)
        })
    }
}

impl CommandTarget for Viewer {
    fn scene(&self) -> &Scene {
        &self.scene
    }

    fn drivable_robots(&self) -> Vec<String> {
        self.slots
            .iter()
            .filter(|s| s.plugin.can_be_active())
            .filter_map(|s| s.plugin.node().and_then(|n| self.scene.get(n)))
            .filter(|o| o.has_tag(ROBOT_TAG))
            .map(|o| o.name.clone())
            .collect()
    }

    fn robot_action(&mut self, robot: &str, action: &str, target: &ObjectRef) -> bool {
        let Some(index) = self.robot_slot(robot) else {
            return false;
        };
        let (plugin, mut ctx) = self.plugin_in_context(index, Instant::now());
        plugin.run_action(action, target, &mut ctx);
        true
    }

    fn robot_to_point(&mut self, robot: &str, point: glam::Vec3) -> bool {
        let Some(index) = self.robot_slot(robot) else {
            return false;
        };
        // A robot takes ground clicks while it is the active handler: one that is not is
        // made so for this click only, without changing which robot the person selected.
        let borrowed = self.active != Some(index);
        if borrowed {
            self.send(index, &InputEvent::Activated(true));
        }
        self.send(index, &InputEvent::GroundClicked(point));
        if borrowed {
            self.send(index, &InputEvent::Activated(false));
        }
        true
    }

    fn stop_robot(&mut self, robot: &str) -> bool {
        let Some(index) = self.robot_slot(robot) else {
            return false;
        };
        self.send(index, &InputEvent::StopAll);
        true
    }

    fn observing(&self) -> bool {
        Viewer::observing(self)
    }
}

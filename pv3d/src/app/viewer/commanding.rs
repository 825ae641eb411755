//! Sentences to the viewer: the command line, a `--script` and speech all end here, parsed
//! with the viewer's grammar against what the scene holds now and carried out by
//! [`crate::commands::executor`] as queries routed like any component's. A line that is
//! itself a `<query …>` is sent as written, so scripts and the command line can ask any
//! component anything. Each reply (or error) is kept for the command line to show.

use std::time::Instant;

use framework::query::Query;

use super::Viewer;
use crate::commands::executor::{CommandTarget, execute};
use crate::commands::vocabulary::ROBOT_TAG;
use crate::commands::{Grammar, Script, Vocabulary, parse};

impl Viewer {
    /// Parses and carries out one sentence; the reply says what was done, the error why not.
    pub fn command(&mut self, sentence: &str) -> Result<String, String> {
        let outcome = if sentence.trim_start().starts_with("<query") {
            self.query_in_xml(sentence.trim())
        } else {
            let vocabulary = Vocabulary::of_scene(&self.scene);
            parse(&self.grammar, &vocabulary, sentence)
                .map_err(|e| e.to_string())
                .and_then(|command| {
                    execute(self, &command).map_err(|e| format!("{}: {e}", sentence.trim()))
                })
        };
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

    /// A `<query>` typed or scripted: the reply's XML, or why there was none.
    fn query_in_xml(&mut self, text: &str) -> Result<String, String> {
        let query = Query::parse(text).map_err(|e| format!("{text}: {e}"))?;
        self.ask(&query)
            .map(|reply| reply.to_xml())
            .map_err(|e| e.to_string())
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
}

impl CommandTarget for Viewer {
    fn drivable_robots(&self) -> Vec<String> {
        self.slots
            .iter()
            .filter(|s| s.plugin.can_be_active())
            .filter_map(|s| s.plugin.node().and_then(|n| self.scene.get(n)))
            .filter(|o| o.has_tag(ROBOT_TAG))
            .map(|o| o.name.clone())
            .collect()
    }

    fn ask(
        &mut self,
        query: &framework::query::Query,
    ) -> Result<framework::query::Reply, framework::query::QueryError> {
        Viewer::ask(self, query)
    }

    fn observing(&self) -> bool {
        Viewer::observing(self)
    }
}

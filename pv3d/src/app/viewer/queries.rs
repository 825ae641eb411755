//! Queries between the viewer's components: the viewer is the post office. A query to
//! `world` is answered from the scene; any other goes to the plugins whose id or library
//! matches, in composition order, until one does it.

use std::time::Instant;

use framework::query::{Addressee, Query, QueryError, Reply, WORLD, answer_world, route};

use super::Viewer;

impl Viewer {
    /// Sends `query` and returns the reply with error 0, or why there was none (the error
    /// names the query and its target). Logged either way, so a reaction's or a script's
    /// query leaves a trace.
    pub fn ask(&mut self, query: &Query) -> Result<Reply, QueryError> {
        let result = self.route_query(query);
        match &result {
            Ok(reply) => {
                tracing::info!(query = %query.to_xml(), reply = %reply.to_xml(), "query answered")
            }
            Err(e) => tracing::warn!("{e}"),
        }
        result
    }

    /// Routes the queries plugins sent during this update and hands each sender its reply.
    pub(super) fn deliver(&mut self, sent: Vec<(usize, Query)>, now: Instant) {
        for (sender, query) in sent {
            let result = self.route_query(&query);
            if let Err(e) = &result {
                tracing::debug!("{e}");
            }
            let (plugin, mut ctx) = self.plugin_in_context(sender, now);
            plugin.on_reply(&query, &result, &mut ctx);
        }
    }

    pub(super) fn route_query(&mut self, query: &Query) -> Result<Reply, QueryError> {
        if query.to.matches(WORLD, WORLD)
            && let Some(reply) = answer_world(query, &self.scene)
            && (reply.is_done() || query.to != framework::query::Target::Everyone)
        {
            return if reply.is_done() {
                Ok(reply)
            } else {
                Err(QueryError::Refused {
                    name: query.name.clone(),
                    to: query.to.clone(),
                    who: WORLD.into(),
                    reply: Box::new(reply),
                })
            };
        }
        // Only the plugins addressed are named (their strings copied): a robot asks the zones
        // about its way ten times a second, and a swarm has a thousand plugins.
        let addressees: Vec<Addressee> = self
            .slots
            .iter()
            .enumerate()
            .filter(|(_, slot)| {
                query
                    .to
                    .matches(slot.instance.id(), slot.instance.library())
            })
            .map(|(index, slot)| Addressee {
                index,
                id: slot.instance.id().to_string(),
                library: slot.instance.library().to_string(),
            })
            .collect();
        let now = Instant::now();
        route(query, addressees, |index, query| {
            let (plugin, mut ctx) = self.plugin_in_context(index, now);
            plugin.answer(query, &mut ctx)
        })
    }
}

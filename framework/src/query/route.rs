//! Passing a query along the components it is addressed to, until one does it.

use super::{Query, QueryError, Reply};

/// A component a query may be passed to: where it is in the caller's list, and the names it
/// answers to.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Addressee {
    pub index: usize,
    pub id: String,
    pub library: String,
}

/// Passes `query` to every addressee whose id or library matches, in order, through `ask`
/// (which calls the plugin's `answer`), and stops at the first reply with error 0. Replies
/// with an error let the query go on; the last of them is returned in
/// [`QueryError::Refused`] when nobody does it. A query nobody takes is
/// [`QueryError::Unanswered`], and one that matches no component
/// [`QueryError::NoSuchComponent`]: each names the query and its target.
pub fn route(
    query: &Query,
    addressees: impl IntoIterator<Item = Addressee>,
    mut ask: impl FnMut(usize, &Query) -> Option<Reply>,
) -> Result<Reply, QueryError> {
    let mut asked = Vec::new();
    let mut refused = None;
    for addressee in addressees {
        if !query.to.matches(&addressee.id, &addressee.library) {
            continue;
        }
        let who = if addressee.id.is_empty() {
            addressee.library.clone()
        } else {
            addressee.id.clone()
        };
        let reply = ask(addressee.index, query);
        tracing::debug!(query = %query.name, to = %query.to, %who, ?reply, "query asked");
        match reply {
            Some(reply) if reply.is_done() => return Ok(reply),
            Some(reply) => refused = Some((who.clone(), reply)),
            None => {}
        }
        asked.push(who);
    }
    let (name, to) = (query.name.clone(), query.to.clone());
    Err(match refused {
        Some((who, reply)) => QueryError::Refused {
            name,
            to,
            who,
            reply: Box::new(reply),
        },
        None if asked.is_empty() => QueryError::NoSuchComponent { name, to },
        None => QueryError::Unanswered { name, to, asked },
    })
}

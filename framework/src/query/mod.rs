//! Inter-component queries: one component asks, others answer, in XML.
//!
//! A [`Query`] is addressed to a [`Target`] — a plugin id or a library name, or everyone — and
//! carries a name ("go to", "which zone") and an XML body. The viewer passes it to every
//! plugin whose id or library matches, in composition order, until one replies with error 0
//! ([`route`]). A [`Reply`] carries an error code (< 0 a problem, 0 done, > 0 the answering
//! component's own code) and an XML body. Typed on the Rust side; on the wire between
//! components, and in compositions and scripts, both are XML:
//!
//! ```
//! use framework::query::{Query, Reply, Target};
//!
//! let q = Query::parse(r#"<query to="robot1" name="go to"><point x="2" y="1"/></query>"#).unwrap();
//! assert_eq!(q.to, Target::Named("robot1".into()));
//! assert_eq!(q.point().unwrap(), (2.0, 1.0));
//! let reply = Reply::done(framework::query::XmlElement::new("ok"));
//! assert_eq!(reply.to_xml(), r#"<reply error="0"><ok/></reply>"#);
//! // A short form: the text is the name, with no body.
//! assert_eq!(Query::parse(r#"<query to="robot1">stop</query>"#).unwrap().name, "stop");
//! ```
//!
//! A component answers by overriding [`Plugin::answer`](crate::plugin::Plugin::answer);
//! `None` means "not mine", so the query goes on to the next addressee.

mod argument_error;
mod element;
mod route;
mod wire;
mod world;

pub use argument_error::ArgumentError;
pub use element::{MAX_ELEMENT_DEPTH, XmlElement};
pub use route::{Addressee, route};
pub use wire::{NotAQuery, XmlError};
pub use world::{WORLD, answer_world};

/// Who a query is for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// Plugins whose id, or library name, is this (`robot1`, `libpv3d_zones`).
    Named(String),
    /// Every plugin, in composition order (`to="*"`).
    Everyone,
}

impl Target {
    /// Reads the `to` attribute: `*` is everyone.
    pub fn parse(text: &str) -> Target {
        match text.trim() {
            "*" => Target::Everyone,
            name => Target::Named(name.to_string()),
        }
    }

    /// Whether a plugin with this id and library is addressed.
    pub fn matches(&self, id: &str, library: &str) -> bool {
        match self {
            Target::Everyone => true,
            Target::Named(name) => name == id || name == library,
        }
    }
}

impl std::fmt::Display for Target {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Target::Everyone => f.write_str("*"),
            Target::Named(name) => f.write_str(name),
        }
    }
}

/// A question (or an order) for other components.
#[derive(Debug, Clone, PartialEq)]
pub struct Query {
    pub to: Target,
    /// What is asked, lower case words: "go to", "which zone", "is there any".
    pub name: String,
    /// The arguments: the `<query>` element's attributes other than `to`/`name`, and its
    /// child elements.
    pub body: XmlElement,
}

/// The error code of a reply that did what was asked.
pub const DONE: i32 = 0;
/// The error code of a reply that understood the query but could not do it.
pub const FAILED: i32 = -1;
/// The error code of a reply to a query whose arguments are missing or wrong.
pub const BAD_ARGUMENTS: i32 = -2;

/// An answer to a [`Query`].
#[derive(Debug, Clone, PartialEq)]
pub struct Reply {
    /// < 0 a problem, 0 done, > 0 a code reserved to the answering component.
    pub error: i32,
    pub body: XmlElement,
}

impl Query {
    /// A query with an empty body.
    pub fn new(to: Target, name: impl Into<String>) -> Query {
        Query {
            to,
            name: name.into(),
            body: XmlElement::new("query"),
        }
    }

    /// The same query with an argument attribute.
    pub fn with_attr(mut self, name: &str, value: impl ToString) -> Query {
        self.body.set_attr(name, value.to_string());
        self
    }

    /// The same query with a child element in its body.
    pub fn with_child(mut self, child: XmlElement) -> Query {
        self.body.children.push(child);
        self
    }

    /// Whether this query is called `name` (case and surrounding spaces ignored).
    pub fn is(&self, name: &str) -> bool {
        self.name.trim().eq_ignore_ascii_case(name)
    }

    /// The point argument: `<point x=".." y=".."/>` in the body, or `x`/`y` on the query.
    pub fn point(&self) -> Result<(f64, f64), ArgumentError> {
        let from = self.body.child("point").unwrap_or(&self.body);
        Ok((from.number("x")?, from.number("y")?))
    }

    /// A named argument: an attribute of the query, else the text of a child element.
    pub fn argument(&self, name: &str) -> Option<String> {
        self.body
            .attr(name)
            .map(str::to_string)
            .or_else(|| self.body.child(name).map(XmlElement::text))
    }
}

impl Reply {
    /// A reply with error 0.
    pub fn done(body: XmlElement) -> Reply {
        Reply { error: DONE, body }
    }

    /// A reply with a problem (`error` < 0) described in a `<message>` body.
    pub fn failed(error: i32, message: impl Into<String>) -> Reply {
        let mut body = XmlElement::new("message");
        body.text = message.into();
        Reply { error, body }
    }

    pub fn is_done(&self) -> bool {
        self.error == DONE
    }
}

/// Why a query got no reply with error 0.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum QueryError {
    /// No plugin has this id or library name.
    #[error("query {name:?} to {to}: no component with that id or library name")]
    NoSuchComponent { name: String, to: Target },
    /// Components were asked but none answered it.
    #[error("query {name:?} to {to}: nobody answered (asked: {})", asked.join(", "))]
    Unanswered {
        name: String,
        to: Target,
        asked: Vec<String>,
    },
    /// Components answered, all with an error; the last one's reply is kept.
    #[error("query {name:?} to {to}: {who} answered error {}: {}", reply.error, reply.body.text)]
    Refused {
        name: String,
        to: Target,
        who: String,
        reply: Box<Reply>,
    },
}

//! What a sentence means once parsed: who, what to do, and to what. Kept small and free of
//! viewer types: the executor turns it into queries.

use glam::Vec2;

/// The robots a command is for.
#[derive(Debug, Clone, PartialEq)]
pub enum Robots {
    All,
    /// By name, as the scene knows them, in the order said.
    Named(Vec<String>),
}

/// What the robots are to do.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verb {
    GoTo,
    Follow,
    Stop,
}

impl Verb {
    /// The verb a grammar's `set="verb=…"` names.
    pub fn from_grammar(name: &str) -> Option<Verb> {
        match name {
            "goto" => Some(Verb::GoTo),
            "follow" => Some(Verb::Follow),
            "stop" => Some(Verb::Stop),
            _ => None,
        }
    }

    /// The names [`Verb::from_grammar`] knows, for error messages.
    pub const GRAMMAR_NAMES: &'static str = "goto, follow, stop";
}

/// What a command acts on.
#[derive(Debug, Clone, PartialEq)]
pub enum Object {
    /// A named zone (`libpv3d_zones`).
    Zone(String),
    /// Another robot, by name.
    Robot(String),
    /// The scene object carrying this tag (`person`).
    Tag(String),
    /// A point on the ground, metres in the world frame.
    Point(Vec2),
}

/// A parsed sentence.
#[derive(Debug, Clone, PartialEq)]
pub struct Command {
    pub robots: Robots,
    pub verb: Verb,
    pub object: Option<Object>,
}

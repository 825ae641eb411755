//! Commands in words: a finite-state grammar declared in XML
//! (`configs/commands.grammar.xml`), a parser that turns a sentence into a small [`Command`]
//! using the names of the live world, the executor that carries a command out through the
//! plugins, and the timed scripts of `pv3d --script`. The command line, scripts and speech
//! all go through the same [`Grammar`], so a sentence means the same wherever it came from.

pub mod command;
pub mod executor;
pub mod grammar;
pub mod parser;
pub mod script;
pub mod vocabulary;

pub use command::{Command, Object, Robots, Verb};
pub use grammar::{Grammar, GrammarError};
pub use parser::{ParseError, parse};
pub use script::{Script, ScriptError, ScriptLine};
pub use vocabulary::Vocabulary;

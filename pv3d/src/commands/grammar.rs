//! The command grammar as declared in XML: named states, each with the word alternatives and
//! live-world slots that lead out of it. Loading checks every reference, so that a mistake in
//! the file is reported at its line and column rather than as a sentence that never parses.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::command::Verb;
use crate::composition::{ConfigError, Element, SourcePos, parse_str};

/// The grammar pv3d ships with, as written in the repository.
const STANDARD_TEXT: &str = include_str!("../../../configs/commands.grammar.xml");
const STANDARD_PATH: &str = "configs/commands.grammar.xml";

/// A grammar file that cannot be used, with where and why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct GrammarError(pub ConfigError);

/// The part of the live world a slot takes its words from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlotKind {
    Robot,
    Zone,
    Tag,
    Point,
}

impl SlotKind {
    fn parse(name: &str) -> Option<SlotKind> {
        match name {
            "robot" => Some(SlotKind::Robot),
            "zone" => Some(SlotKind::Zone),
            "tag" => Some(SlotKind::Tag),
            "point" => Some(SlotKind::Point),
            _ => None,
        }
    }

    /// How an error message speaks of what was expected: "a robot".
    pub fn describe(self) -> &'static str {
        match self {
            SlotKind::Robot => "a robot",
            SlotKind::Zone => "a zone",
            SlotKind::Tag => "a tag",
            SlotKind::Point => "a point (x y)",
        }
    }
}

/// Whether a slot names the robots commanded or what they act on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fills {
    Subject,
    Object,
}

/// What saying some words records.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Setting {
    AllRobots,
    Verb(Verb),
}

/// How a transition consumes words.
#[derive(Debug, Clone, PartialEq)]
pub enum Step {
    /// One of these phrases (lower-case words).
    Words {
        phrases: Vec<Vec<String>>,
        set: Option<Setting>,
    },
    /// A name from the live world.
    Slot { kind: SlotKind, fills: Fills },
}

/// A way out of a state.
#[derive(Debug, Clone, PartialEq)]
pub struct Transition {
    pub step: Step,
    pub next: usize,
}

#[derive(Debug, Clone, PartialEq)]
pub struct State {
    pub name: String,
    pub is_final: bool,
    pub transitions: Vec<Transition>,
}

/// A loaded, checked grammar.
#[derive(Debug, Clone, PartialEq)]
pub struct Grammar {
    pub states: Vec<State>,
    pub start: usize,
}

impl Grammar {
    /// The grammar of `configs/commands.grammar.xml`, built into the program.
    pub fn standard() -> Grammar {
        Grammar::from_str(STANDARD_TEXT, Path::new(STANDARD_PATH))
            .expect("the shipped grammar is checked by the tests")
    }

    pub fn load(path: &Path) -> Result<Grammar, GrammarError> {
        let text = std::fs::read_to_string(path).map_err(|e| {
            GrammarError(ConfigError::Io {
                path: path.to_path_buf(),
                message: e.to_string(),
            })
        })?;
        Grammar::from_str(&text, path)
    }

    /// Reads grammar XML; `path` names the file in error messages.
    pub fn from_str(text: &str, path: &Path) -> Result<Grammar, GrammarError> {
        let root = parse_str(text, Arc::new(PathBuf::from(path))).map_err(GrammarError)?;
        read_grammar(&root).map_err(GrammarError)
    }
}

fn read_grammar(root: &Element) -> Result<Grammar, ConfigError> {
    if root.local_name() != "commandGrammar" {
        return Err(ConfigError::at(
            root.pos.clone(),
            format!("expected <commandGrammar>, found <{}>", root.name),
        ));
    }
    let state_elements: Vec<&Element> = root.elements().filter(|e| e.name == "state").collect();
    if let Some(other) = root.elements().find(|e| e.name != "state") {
        return Err(ConfigError::at(
            other.pos.clone(),
            format!(
                "<commandGrammar> holds <state> elements, not <{}>",
                other.name
            ),
        ));
    }
    let mut names: Vec<String> = Vec::new();
    for e in &state_elements {
        let name = required(e, "name")?;
        if names.iter().any(|n| n == name) {
            return Err(ConfigError::at(
                e.pos.clone(),
                format!("state {name:?} is declared twice"),
            ));
        }
        names.push(name.to_string());
    }
    let index_of = |name: &str, pos: &SourcePos| {
        names.iter().position(|n| n == name).ok_or_else(|| {
            ConfigError::at(
                pos.clone(),
                format!("no state named {name:?}; states: {}", names.join(", ")),
            )
        })
    };
    let start_name = required(root, "start")?;
    let start = index_of(start_name, &root.pos)?;
    let mut states = Vec::new();
    for (e, name) in state_elements.iter().zip(&names) {
        let is_final = match e.attr("final") {
            None | Some("false") => false,
            Some("true") => true,
            Some(other) => {
                return Err(ConfigError::at(
                    e.pos.clone(),
                    format!("final is true or false, not {other:?}"),
                ));
            }
        };
        let mut transitions = Vec::new();
        for t in e.elements() {
            let step = match t.name.as_str() {
                "words" => read_words(t)?,
                "slot" => read_slot(t)?,
                other => {
                    return Err(ConfigError::at(
                        t.pos.clone(),
                        format!("a <state> holds <words> and <slot>, not <{other}>"),
                    ));
                }
            };
            let next = index_of(required(t, "next")?, &t.pos)?;
            transitions.push(Transition { step, next });
        }
        states.push(State {
            name: name.clone(),
            is_final,
            transitions,
        });
    }
    Ok(Grammar { states, start })
}

fn required<'a>(e: &'a Element, name: &str) -> Result<&'a str, ConfigError> {
    e.attr(name)
        .map(str::trim)
        .filter(|v| !v.is_empty())
        .ok_or_else(|| {
            ConfigError::at(
                e.pos.clone(),
                format!("<{}> needs a {name} attribute", e.name),
            )
        })
}

fn read_words(e: &Element) -> Result<Step, ConfigError> {
    let mut phrases = Vec::new();
    for alternative in required(e, "say")?.split('|') {
        let words: Vec<String> = alternative
            .split_whitespace()
            .map(str::to_lowercase)
            .collect();
        if words.is_empty() {
            return Err(ConfigError::at(
                e.pos.clone(),
                "an alternative in say is empty (two | in a row?)",
            ));
        }
        phrases.push(words);
    }
    let set = e.attr("set").map(|s| read_setting(e, s)).transpose()?;
    Ok(Step::Words { phrases, set })
}

fn read_setting(e: &Element, text: &str) -> Result<Setting, ConfigError> {
    let bad = |message: String| ConfigError::at(e.pos.clone(), message);
    match text.trim().split_once('=') {
        Some(("robots", "all")) => Ok(Setting::AllRobots),
        Some(("verb", verb)) => Verb::from_grammar(verb).map(Setting::Verb).ok_or_else(|| {
            bad(format!(
                "unknown verb {verb:?}; verbs: {}",
                Verb::GRAMMAR_NAMES
            ))
        }),
        _ => Err(bad(format!("set is robots=all or verb=NAME, not {text:?}"))),
    }
}

fn read_slot(e: &Element) -> Result<Step, ConfigError> {
    let kind_text = required(e, "kind")?;
    let kind = SlotKind::parse(kind_text).ok_or_else(|| {
        ConfigError::at(
            e.pos.clone(),
            format!("unknown slot kind {kind_text:?}; kinds: robot, zone, tag, point"),
        )
    })?;
    let fills = match required(e, "fills")? {
        "subject" => Fills::Subject,
        "object" => Fills::Object,
        other => {
            return Err(ConfigError::at(
                e.pos.clone(),
                format!("fills is subject or object, not {other:?}"),
            ));
        }
    };
    if fills == Fills::Subject && kind != SlotKind::Robot {
        return Err(ConfigError::at(
            e.pos.clone(),
            "only a robot slot can fill the subject",
        ));
    }
    Ok(Step::Slot { kind, fills })
}

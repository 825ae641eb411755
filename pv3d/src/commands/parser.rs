//! Parsing a sentence with a [`Grammar`]: a search over the states, trying every way the next
//! words can be read (longest phrases and names first) and backing up when a path dead-ends.
//! When no path reaches a final state, the error speaks of the furthest word any path got
//! to, which is where the sentence went wrong.

use glam::Vec2;

use super::command::{Command, Object, Robots, Verb};
use super::grammar::{Fills, Grammar, Setting, SlotKind, Step};
use super::vocabulary::Vocabulary;

/// A sentence the grammar does not accept; the message quotes it and says what was expected.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{sentence}: {message}")]
pub struct ParseError {
    pub sentence: String,
    pub message: String,
}

/// What has been understood so far along one path.
#[derive(Debug, Clone, Default)]
struct Understood {
    all: bool,
    robots: Vec<String>,
    verb: Option<Verb>,
    object: Option<Object>,
}

/// What reading a few words adds.
enum Reading {
    Set(Option<Setting>),
    Robot(String),
    Object(Object),
}

/// The furthest any path got: the word it could not read, and in which state.
#[derive(Default)]
struct Furthest {
    word: usize,
    state: usize,
}

/// Parses `sentence` with `grammar`, taking names from `vocabulary`.
pub fn parse(
    grammar: &Grammar,
    vocabulary: &Vocabulary,
    sentence: &str,
) -> Result<Command, ParseError> {
    let sentence = sentence.trim();
    let words = tokens(sentence);
    let fail = |message: String| ParseError {
        sentence: sentence.to_string(),
        message,
    };
    if words.is_empty() {
        return Err(fail("nothing to do: the sentence is empty".into()));
    }
    let mut furthest = Furthest {
        word: 0,
        state: grammar.start,
    };
    let search = Search {
        grammar,
        vocabulary,
        words: &words,
    };
    match search.walk(grammar.start, 0, Understood::default(), &mut furthest) {
        Some(understood) => to_command(understood).map_err(fail),
        None => Err(fail(search.explain(&furthest))),
    }
}

/// Lower-case words, with the punctuation around them dropped.
fn tokens(sentence: &str) -> Vec<String> {
    sentence
        .split_whitespace()
        .map(|w| {
            w.trim_matches(|c: char| matches!(c, ',' | '!' | '?' | ';' | ':' | '(' | ')'))
                .trim_end_matches('.')
                .to_lowercase()
        })
        .filter(|w| !w.is_empty())
        .collect()
}

fn to_command(understood: Understood) -> Result<Command, String> {
    let verb = understood
        .verb
        .ok_or("the grammar accepted it without a verb (set=\"verb=…\")")?;
    let robots = if understood.all {
        Robots::All
    } else if understood.robots.is_empty() {
        return Err("it names no robot".into());
    } else {
        Robots::Named(understood.robots)
    };
    if verb != Verb::Stop && understood.object.is_none() {
        return Err("go to or follow what?".into());
    }
    Ok(Command {
        robots,
        verb,
        object: understood.object,
    })
}

struct Search<'a> {
    grammar: &'a Grammar,
    vocabulary: &'a Vocabulary,
    words: &'a [String],
}

impl Search<'_> {
    fn walk(
        &self,
        state: usize,
        at: usize,
        understood: Understood,
        furthest: &mut Furthest,
    ) -> Option<Understood> {
        if at == self.words.len() && self.grammar.states[state].is_final {
            return Some(understood);
        }
        if at >= furthest.word {
            *furthest = Furthest { word: at, state };
        }
        for transition in &self.grammar.states[state].transitions {
            for (length, reading) in self.readings(&transition.step, at) {
                let mut next = understood.clone();
                apply(&mut next, reading);
                if let Some(done) = self.walk(transition.next, at + length, next, furthest) {
                    return Some(done);
                }
            }
        }
        None
    }

    /// Every way `step` can read the words from `at`, longest first.
    fn readings(&self, step: &Step, at: usize) -> Vec<(usize, Reading)> {
        let rest = &self.words[at..];
        let mut found: Vec<(usize, Reading)> = match step {
            Step::Words { phrases, set } => phrases
                .iter()
                .filter(|p| rest.starts_with(p))
                .map(|p| (p.len(), Reading::Set(*set)))
                .collect(),
            Step::Slot { kind, fills } => {
                let names = |list: &[String]| -> Vec<(usize, String)> {
                    list.iter()
                        .filter_map(|name| {
                            let said: Vec<String> =
                                name.split_whitespace().map(str::to_lowercase).collect();
                            (!said.is_empty() && rest.starts_with(&said))
                                .then(|| (said.len(), name.clone()))
                        })
                        .collect()
                };
                match kind {
                    SlotKind::Robot => names(&self.vocabulary.robots)
                        .into_iter()
                        .map(|(n, name)| match fills {
                            Fills::Subject => (n, Reading::Robot(name)),
                            Fills::Object => (n, Reading::Object(Object::Robot(name))),
                        })
                        .collect(),
                    SlotKind::Zone => names(&self.vocabulary.zones)
                        .into_iter()
                        .map(|(n, name)| (n, Reading::Object(Object::Zone(name))))
                        .collect(),
                    SlotKind::Tag => names(&self.vocabulary.tags)
                        .into_iter()
                        .map(|(n, name)| (n, Reading::Object(Object::Tag(name))))
                        .collect(),
                    SlotKind::Point => point(rest)
                        .map(|p| (2, Reading::Object(Object::Point(p))))
                        .into_iter()
                        .collect(),
                }
            }
        };
        found.sort_by_key(|(length, _)| std::cmp::Reverse(*length));
        found
    }

    /// What went wrong where the furthest path stopped.
    fn explain(&self, furthest: &Furthest) -> String {
        let state = &self.grammar.states[furthest.state];
        let mut phrases = Vec::new();
        let mut slots = Vec::new();
        for transition in &state.transitions {
            match &transition.step {
                Step::Words { phrases: p, .. } => {
                    phrases.extend(p.iter().map(|words| words.join(" ")))
                }
                Step::Slot { kind, .. } if !slots.contains(kind) => slots.push(*kind),
                Step::Slot { .. } => {}
            }
        }
        let said = self.words[..furthest.word].join(" ");
        let Some(word) = self.words.get(furthest.word) else {
            return format!(
                "incomplete: after \"{said}\" expected {}",
                self.expected(&phrases, &slots)
            );
        };
        let mut message = if slots.is_empty() {
            format!("did not expect \"{word}\"")
        } else {
            let kinds: Vec<&str> = slots.iter().map(|k| kind_noun(*k)).collect();
            format!("no {} named {word}", kinds.join(" or "))
        };
        if !said.is_empty() {
            message.push_str(&format!(" after \"{said}\""));
        }
        message.push_str(&format!("; expected {}", self.expected(&phrases, &slots)));
        message
    }

    /// "robots: r0, r1; or say: all robots, …".
    fn expected(&self, phrases: &[String], slots: &[SlotKind]) -> String {
        let mut parts = Vec::new();
        for kind in slots {
            let known = match kind {
                SlotKind::Robot => &self.vocabulary.robots,
                SlotKind::Zone => &self.vocabulary.zones,
                SlotKind::Tag => &self.vocabulary.tags,
                SlotKind::Point => {
                    parts.push(format!("{} in metres", kind.describe()));
                    continue;
                }
            };
            let names = if known.is_empty() {
                "none here".to_string()
            } else {
                known.join(", ")
            };
            parts.push(format!("{}s: {names}", kind_noun(*kind)));
        }
        if !phrases.is_empty() {
            let lead = if parts.is_empty() { "" } else { "or say: " };
            parts.push(format!("{lead}{}", phrases.join(", ")));
        }
        parts.join("; ")
    }
}

fn kind_noun(kind: SlotKind) -> &'static str {
    match kind {
        SlotKind::Robot => "robot",
        SlotKind::Zone => "zone",
        SlotKind::Tag => "tag",
        SlotKind::Point => "point",
    }
}

fn apply(understood: &mut Understood, reading: Reading) {
    match reading {
        Reading::Set(None) => {}
        Reading::Set(Some(Setting::AllRobots)) => understood.all = true,
        Reading::Set(Some(Setting::Verb(verb))) => understood.verb = Some(verb),
        Reading::Robot(name) => {
            if !understood.robots.contains(&name) {
                understood.robots.push(name);
            }
        }
        Reading::Object(object) => understood.object = Some(object),
    }
}

/// Two numbers in a row: x and y in metres.
fn point(words: &[String]) -> Option<Vec2> {
    let number = |w: &String| w.parse::<f32>().ok().filter(|v| v.is_finite());
    match words {
        [x, y, ..] => Some(Vec2::new(number(x)?, number(y)?)),
        _ => None,
    }
}

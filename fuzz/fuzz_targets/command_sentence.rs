//! What a person types on the command line (or a script says), parsed by the shipped grammar
//! against a small vocabulary: a command or an error that says why — never a panic.
#![no_main]

use std::sync::OnceLock;

use libfuzzer_sys::fuzz_target;
use pv3d::commands::{Grammar, Vocabulary, parse};

fn grammar() -> &'static Grammar {
    static GRAMMAR: OnceLock<Grammar> = OnceLock::new();
    GRAMMAR.get_or_init(Grammar::standard)
}

fuzz_target!(|sentence: &str| {
    let vocabulary = Vocabulary {
        robots: vec!["robot1".into(), "robot2".into(), "r0".into()],
        zones: vec!["charging".into(), "keep out".into()],
        tags: vec!["person".into(), "marker".into()],
    };
    if let Err(e) = parse(grammar(), &vocabulary, sentence) {
        assert!(!e.to_string().is_empty());
    }
});

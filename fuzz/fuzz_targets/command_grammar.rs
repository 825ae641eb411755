//! A grammar file someone wrote (`pv3d --grammar mine.xml`), then sentences parsed with it: the
//! grammar is refused with `file:line:col`, or every sentence parses or fails cleanly — never a
//! panic, never a loop.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;
use pv3d::commands::{Grammar, Vocabulary, parse};

fuzz_target!(|text: &str| {
    // The first line is a sentence to try, the rest the grammar.
    let (sentence, grammar_text) = text.split_once('\n').unwrap_or(("robot1 stop", text));
    match Grammar::from_str(grammar_text, Path::new("fuzz.grammar.xml")) {
        Ok(grammar) => {
            let vocabulary = Vocabulary {
                robots: vec!["robot1".into()],
                zones: vec!["charging".into()],
                tags: vec!["marker".into()],
            };
            for sentence in [sentence, "robot1 go to charging", "all robots stop", ""] {
                let _ = parse(&grammar, &vocabulary, sentence);
            }
        }
        Err(e) => assert!(e.to_string().starts_with("fuzz.grammar.xml:"), "{e}"),
    }
});

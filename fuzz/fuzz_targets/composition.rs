//! The composition reader on arbitrary text: a composition, or an error that names its place
//! as `file:line:col` — never a panic.
#![no_main]

use std::path::PathBuf;
use std::sync::Arc;

use libfuzzer_sys::fuzz_target;
use pv3d::composition::{Composition, ParserRegistry, parse_str};

fuzz_target!(|text: &str| {
    match parse_str(text, Arc::new(PathBuf::from("fuzz.xml"))) {
        Ok(root) => {
            if let Err(e) = Composition::from_root(&root, &ParserRegistry::standard()) {
                assert!(e.to_string().starts_with("fuzz.xml:"), "{e}");
            }
        }
        Err(e) => assert!(e.to_string().starts_with("fuzz.xml:"), "{e}"),
    }
});

//! A `--script` file (`<seconds> <sentence>` a line): read, or refused naming `file:line` —
//! never a panic.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;
use pv3d::commands::Script;

fuzz_target!(|text: &str| {
    if let Err(e) = Script::from_str(text, Path::new("fuzz.txt")) {
        assert!(e.to_string().starts_with("fuzz.txt:"), "{e}");
    }
});

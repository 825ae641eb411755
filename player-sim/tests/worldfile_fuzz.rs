//! The world-file reader on arbitrary and mangled text: an error with file:line:col, or items —
//! never a panic.

use player_sim::worldfile::parse_text;
use proptest::prelude::*;

const SAMPLE: &str = "include \"robots.inc\"\ninterval_sim 100\ndefine lidar ranger ( sensor( range [ 0 8 ] fov 180 samples 181 ) )\nrover( name \"r0\" pose [ -7 -4 0 30 ] lidar( pose [ 0.1 0 0 0 ] ) )\n";

fn check(text: &str) {
    if let Err(e) = parse_text(text, "fuzz.world") {
        assert!(e.to_string().starts_with("fuzz.world:"), "{e}");
        assert!(e.line >= 1 && e.col >= 1);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,200}") {
        check(&text);
    }

    #[test]
    fn mangled_worlds_fail_with_a_position(cut in 0..SAMPLE.len(), insert in "[()\\[\\]\"# a-z0-9.-]{0,6}") {
        let mut text = SAMPLE.to_string();
        text.insert_str(cut, &insert);
        check(&text);
        check(&SAMPLE[..cut]);
    }
}

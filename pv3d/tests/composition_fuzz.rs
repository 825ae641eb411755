//! The composition reader on arbitrary and mangled text: an error with a position, or a
//! composition — never a panic.

use std::path::PathBuf;
use std::sync::Arc;

use proptest::prelude::*;
use pv3d::composition::{Composition, ParserRegistry, parse_str};

const SAMPLE: &str = r#"<pv3d xmlns:xi="http://www.w3.org/2001/XInclude">
  <handlers>
    <playerClient host="localhost" port="6665"/>
    <playerDeviceMask mask="laser:sicklms200:*"><plugin library="libpv3d_laser" id="l"><fill>1</fill></plugin></playerDeviceMask>
  </handlers>
  <plugin library="libpv3d_ground"/>
</pv3d>"#;

fn check(text: &str) {
    match parse_str(text, Arc::new(PathBuf::from("fuzz.xml"))) {
        Ok(root) => {
            if let Err(e) = Composition::from_root(&root, &ParserRegistry::new(&["zone"])) {
                assert!(e.to_string().starts_with("fuzz.xml:"), "{e}");
            }
        }
        Err(e) => assert!(e.to_string().starts_with("fuzz.xml:"), "{e}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,200}") {
        check(&text);
    }

    #[test]
    fn mangled_compositions_fail_with_a_position(cut in 0..SAMPLE.len(), insert in "[<>/=\"'&a-z ]{0,6}") {
        let mut text = SAMPLE.to_string();
        let at = (0..=cut).rev().find(|&i| text.is_char_boundary(i)).unwrap_or(0);
        text.insert_str(at, &insert);
        check(&text);
        check(&SAMPLE[..at]);
    }
}

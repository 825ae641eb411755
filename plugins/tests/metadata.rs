//! Every standard component says who wrote it, how to reach them, where to read more and what
//! it is for: the item tree shows it, so none may be left blank.

#[test]
fn every_standard_component_carries_its_metadata() {
    let registry = plugins::standard_plugins();
    let mut descriptions = Vec::new();
    for library in registry.libraries() {
        let about = registry.find(library).expect("registered").metadata;
        assert!(!about.author.trim().is_empty(), "{library}: no author");
        assert!(about.email.contains('@'), "{library}: {:?}", about.email);
        assert!(
            about.web_page.starts_with("https://"),
            "{library}: {:?}",
            about.web_page
        );
        assert!(
            about.description.ends_with('.'),
            "{library}: a sentence, not {:?}",
            about.description
        );
        descriptions.push(about.description);
    }
    let count = descriptions.len();
    descriptions.sort();
    descriptions.dedup();
    assert_eq!(descriptions.len(), count, "each says what it alone is for");
}

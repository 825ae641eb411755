//! The command grammar: the shipped XML loads, sentences become commands with names from the
//! live world, bad sentences and bad grammar files are reported with what and where.

use std::path::Path;

use glam::Vec2;
use pv3d::commands::{Command, Grammar, Object, Robots, Verb, Vocabulary, parse};

fn world() -> Vocabulary {
    Vocabulary {
        robots: vec!["robot1".into(), "robot2".into(), "big red".into()],
        zones: vec!["charging".into(), "teacher corner".into()],
        tags: vec!["person".into(), "landmark".into()],
    }
}

fn said(sentence: &str) -> Command {
    parse(&Grammar::standard(), &world(), sentence).unwrap_or_else(|e| panic!("{e}"))
}

fn refused(sentence: &str) -> String {
    match parse(&Grammar::standard(), &world(), sentence) {
        Ok(c) => panic!("{sentence:?} was accepted as {c:?}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn the_issues_sentences_parse() {
    assert_eq!(
        said("robot2 go to charging"),
        Command {
            robots: Robots::Named(vec!["robot2".into()]),
            verb: Verb::GoTo,
            object: Some(Object::Zone("charging".into())),
        }
    );
    assert_eq!(
        said("all robots stop"),
        Command {
            robots: Robots::All,
            verb: Verb::Stop,
            object: None,
        }
    );
    assert_eq!(
        said("robot1 follow the person"),
        Command {
            robots: Robots::Named(vec!["robot1".into()]),
            verb: Verb::Follow,
            object: Some(Object::Tag("person".into())),
        }
    );
}

#[test]
fn case_punctuation_several_robots_multi_word_names_and_points() {
    let c = said("Robot1 and robot2, go to the Teacher Corner please.");
    assert_eq!(
        c.robots,
        Robots::Named(vec!["robot1".into(), "robot2".into()])
    );
    assert_eq!(c.object, Some(Object::Zone("teacher corner".into())));
    let c = said("big red drive to 2.5 -1");
    assert_eq!(c.robots, Robots::Named(vec!["big red".into()]));
    assert_eq!(c.object, Some(Object::Point(Vec2::new(2.5, -1.0))));
    assert_eq!(
        said("robot1 follow robot2").object,
        Some(Object::Robot("robot2".into()))
    );
    // "go" alone is a verb too, but "go to" must be read as one when it fits.
    assert_eq!(
        said("robot1 go to landmark").object,
        Some(Object::Tag("landmark".into()))
    );
}

#[test]
fn an_unknown_robot_is_named_with_the_robots_there_are() {
    let e = refused("robot9 go to charging");
    assert!(
        e.starts_with("robot9 go to charging: no robot named robot9;"),
        "{e}"
    );
    assert!(e.contains("robots: robot1, robot2, big red"), "{e}");
}

#[test]
fn other_mistakes_say_what_was_expected_there() {
    let e = refused("robot1 fly to charging");
    assert!(e.contains("did not expect \"fly\" after \"robot1\""), "{e}");
    assert!(e.contains("go to") && e.contains("follow"), "{e}");
    let e = refused("robot1 go to");
    assert!(e.contains("incomplete: after \"robot1 go to\""), "{e}");
    assert!(e.contains("zones: charging, teacher corner"), "{e}");
    let e = refused("robot1 go to kitchen");
    assert!(
        e.contains("no zone or robot or tag or point named kitchen"),
        "{e}"
    );
    let e = refused("robot1 stop now now robot2");
    assert!(e.contains("did not expect \"robot2\""), "{e}");
    assert!(refused("   ").contains("empty"));
    // Following a point parses as nothing: points are only places to go to.
    assert!(refused("robot1 follow 1 2").contains("no robot or tag named 1"));
}

#[test]
fn an_empty_world_says_there_is_nothing_to_name() {
    let e = parse(&Grammar::standard(), &Vocabulary::default(), "r0 stop").unwrap_err();
    assert!(e.to_string().contains("robots: none here"), "{e}");
}

fn grammar_error(xml: &str) -> String {
    Grammar::from_str(xml, Path::new("bad.grammar.xml"))
        .expect_err("a broken grammar is refused")
        .to_string()
}

#[test]
fn a_broken_grammar_file_is_reported_at_its_line_and_column() {
    let e = grammar_error(
        "<commandGrammar start=\"a\">\n  <state name=\"a\">\n    <words say=\"x\" next=\"b\"/>\n  </state>\n</commandGrammar>\n",
    );
    assert!(e.starts_with("bad.grammar.xml:3:5:"), "{e}");
    assert!(e.contains("no state named \"b\"; states: a"), "{e}");
    let e = grammar_error(
        "<commandGrammar start=\"a\">\n<state name=\"a\" final=\"true\">\n<slot kind=\"colour\" fills=\"object\" next=\"a\"/>\n</state>\n</commandGrammar>",
    );
    assert!(e.starts_with("bad.grammar.xml:3:1:"), "{e}");
    assert!(e.contains("unknown slot kind \"colour\""), "{e}");
    let e = grammar_error(
        "<commandGrammar start=\"a\"><state name=\"a\"><words say=\"x||y\" next=\"a\"/></state></commandGrammar>",
    );
    assert!(e.contains("empty"), "{e}");
    let e = grammar_error(
        "<commandGrammar start=\"a\"><state name=\"a\"><words say=\"x\" set=\"verb=fly\" next=\"a\"/></state></commandGrammar>",
    );
    assert!(e.contains("unknown verb \"fly\""), "{e}");
    assert!(grammar_error("<commandGrammar start=\"a\"><state").starts_with("bad.grammar.xml:1:"));
    assert!(grammar_error("<grammar/>").contains("expected <commandGrammar>"));
}

#[test]
fn the_shipped_file_is_the_built_in_grammar() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs/commands.grammar.xml");
    assert_eq!(
        Grammar::load(&path).unwrap().states,
        Grammar::standard().states
    );
    assert!(Grammar::load(Path::new("/nonexistent.xml")).is_err());
}

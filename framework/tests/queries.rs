//! Queries on the wire and along the components: parsing with positions, printing, routing
//! until error 0, and the errors that name what nobody answered.

use framework::query::{
    Addressee, BAD_ARGUMENTS, FAILED, Query, QueryError, Reply, Target, XmlElement, answer_world,
    route,
};
use framework::scene::{Object3D, Scene};

fn addressees(names: &[(&str, &str)]) -> Vec<Addressee> {
    names
        .iter()
        .enumerate()
        .map(|(index, (id, library))| Addressee {
            index,
            id: id.to_string(),
            library: library.to_string(),
        })
        .collect()
}

#[test]
fn a_query_reads_its_target_name_and_arguments() {
    let q = Query::parse(
        r#"<query to="libpv3d_zones" name="which zone"><point x="1.5" y="-2"/></query>"#,
    )
    .unwrap();
    assert_eq!(q.to, Target::Named("libpv3d_zones".into()));
    assert!(q.is("Which Zone"));
    assert_eq!(q.point().unwrap(), (1.5, -2.0));
}

#[test]
fn the_short_form_takes_its_text_as_the_name() {
    let q = Query::parse("<query to=\"*\">\n  stop\n</query>").unwrap();
    assert_eq!(q.to, Target::Everyone);
    assert_eq!(q.name, "stop");
}

#[test]
fn a_query_prints_and_reads_back_the_same() {
    let q = Query::new(Target::Named("robot1".into()), "go to")
        .with_attr("x", 3)
        .with_child(XmlElement::new("note").with_text("a < b & \"c\""));
    let text = q.to_xml();
    assert_eq!(Query::parse(&text).unwrap(), q, "{text}");
}

#[test]
fn a_reply_prints_and_reads_back_the_same() {
    let reply = Reply::failed(FAILED, "no map yet");
    assert_eq!(
        reply.to_xml(),
        r#"<reply error="-1"><message>no map yet</message></reply>"#
    );
    assert_eq!(Reply::parse(&reply.to_xml()).unwrap(), reply);
}

#[test]
fn malformed_xml_is_an_error_with_line_and_column() {
    let err = Query::parse("<query to=\"a\" name=\"b\">\n  <point x=\"1\">\n</query>").unwrap_err();
    assert_eq!(err.line, 3, "{err}");
    assert!(err.to_string().starts_with("3:"), "{err}");
    let err = Query::parse("<query to=\"a\">go</query>\n<query/>").unwrap_err();
    assert_eq!((err.line, err.column), (2, 1), "{err}");
}

#[test]
fn elements_nested_too_deep_are_an_error_not_a_stack_overflow() {
    let levels = 100_000;
    let text = format!(
        "<query to=\"a\" name=\"b\">{}{}</query>",
        "<p>".repeat(levels),
        "</p>".repeat(levels)
    );
    let err = Query::parse(&text).unwrap_err();
    assert!(err.message.contains("nested more than 256 deep"), "{err}");
    assert_eq!(err.line, 1);
}

#[test]
fn a_query_without_target_or_name_says_so() {
    assert!(
        Query::parse("<query name=\"x\"/>")
            .unwrap_err()
            .message
            .contains("to attribute")
    );
    assert!(
        Query::parse("<query to=\"a\"/>")
            .unwrap_err()
            .message
            .contains("no name")
    );
    assert!(
        Reply::parse("<reply error=\"x\"/>")
            .unwrap_err()
            .message
            .contains("integer")
    );
}

#[test]
fn a_missing_point_names_the_attribute() {
    let q = Query::parse(r#"<query to="z" name="which zone"><point x="1"/></query>"#).unwrap();
    assert!(
        q.point()
            .unwrap_err()
            .to_string()
            .contains("no y attribute")
    );
}

#[test]
fn routing_stops_at_the_first_component_that_does_it() {
    let q = Query::new(Target::Named("libpv3d_zones".into()), "which zone");
    let mut asked = Vec::new();
    let reply = route(
        &q,
        addressees(&[
            ("a", "libpv3d_zones"),
            ("b", "libpv3d_laser"),
            ("c", "libpv3d_zones"),
            ("d", "libpv3d_zones"),
        ]),
        |index, _| {
            asked.push(index);
            match index {
                0 => None,
                2 => Some(Reply::done(XmlElement::new("zone"))),
                _ => panic!("asked {index} after the answer, or not addressed"),
            }
        },
    )
    .unwrap();
    assert_eq!(reply.body.name, "zone");
    assert_eq!(asked, vec![0, 2]);
}

#[test]
fn a_query_nobody_answers_names_the_query_and_who_was_asked() {
    let q = Query::new(Target::Named("robot1".into()), "dance");
    let err = route(
        &q,
        addressees(&[("robot1", "libpv3d_position2d")]),
        |_, _| None,
    )
    .unwrap_err();
    assert!(matches!(err, QueryError::Unanswered { ref asked, .. } if asked == &["robot1"]));
    assert!(err.to_string().contains("\"dance\""), "{err}");
    assert!(err.to_string().contains("robot1"), "{err}");
}

#[test]
fn a_query_to_nobody_says_there_is_no_such_component() {
    let q = Query::new(Target::Named("robot9".into()), "stop");
    let err = route(
        &q,
        addressees(&[("robot1", "libpv3d_position2d")]),
        |_, _| panic!("nobody is addressed"),
    )
    .unwrap_err();
    assert!(matches!(err, QueryError::NoSuchComponent { .. }), "{err}");
}

#[test]
fn errors_let_the_query_go_on_and_the_last_is_kept() {
    let q = Query::new(Target::Everyone, "go to");
    let err = route(&q, addressees(&[("a", "x"), ("b", "y")]), |index, _| {
        Some(Reply::failed(-10 - index as i32, format!("not me {index}")))
    })
    .unwrap_err();
    match err {
        QueryError::Refused { who, reply, .. } => {
            assert_eq!(who, "b");
            assert_eq!(reply.error, -11);
        }
        other => panic!("{other}"),
    }
}

#[test]
fn the_world_answers_whether_there_is_any_tagged_object() {
    let mut scene = Scene::new();
    let mut person = Object3D::new("person 1");
    person.tags.push("person".into());
    scene.add(person);
    scene.add(Object3D::new("chair"));
    let ask = |tag: &str| {
        answer_world(
            &Query::new(Target::Named("world".into()), "is there any").with_attr("tag", tag),
            &scene,
        )
        .unwrap()
    };
    let yes = ask("person");
    assert!(yes.is_done());
    assert_eq!(yes.body.attr("count"), Some("1"));
    assert_eq!(yes.body.children[0].attr("name"), Some("person 1"));
    assert_eq!(ask("robot").body.attr("count"), Some("0"));
    let no_tag = answer_world(
        &Query::new(Target::Named("world".into()), "is there any"),
        &scene,
    )
    .unwrap();
    assert_eq!(no_tag.error, BAD_ARGUMENTS);
    assert!(answer_world(&Query::new(Target::Everyone, "stop"), &scene).is_none());
}

#[test]
fn every_truncation_and_mangling_of_a_query_is_an_error_or_a_query_never_a_panic() {
    let text = "<query to=\"robot1\" name=\"go to\">\n  <point x=\"1\" y=\"2\"/>\n  <note>a &amp; b</note>\n</query>";
    let lines = text.lines().count();
    for end in 0..text.len() {
        if let Err(e) = Query::parse(&text[..end]) {
            assert!(
                e.line >= 1 && e.line <= lines && e.column >= 1,
                "{end}: {e}"
            );
        }
    }
    for (i, _) in text.char_indices() {
        for replacement in ["<", ">", "&", "\"", "/", "é", ""] {
            let mangled = format!("{}{replacement}{}", &text[..i], &text[i + 1..]);
            if let Err(e) = Query::parse(&mangled) {
                assert!(e.line >= 1 && e.column >= 1, "{mangled:?}: {e}");
            }
            let _ = Reply::parse(&mangled);
        }
    }
}

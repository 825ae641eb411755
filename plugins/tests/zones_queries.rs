//! The zones manager answers "which zone" for a point and for a named object, and "where is"
//! a zone.

mod support;

use framework::config::{Param, PluginConfig};
use framework::query::{BAD_ARGUMENTS, FAILED, Query, Target, XmlElement};
use framework::scene::Object3D;
use glam::{Affine3A, Vec3};
use support::harness;

fn zone(name: &str, corners: &str) -> Param {
    let mut p = Param::new("zone", corners);
    p.attributes = vec![("name".into(), name.into())];
    p
}

fn zones_config() -> PluginConfig {
    PluginConfig {
        library: "libpv3d_zones".into(),
        id: "zones".into(),
        params: vec![
            zone("keep out", "0 0  2 0  2 2  0 2"),
            zone("stairs", "1 1  3 1  3 3  1 3"),
        ],
        ..PluginConfig::default()
    }
}

fn to() -> Target {
    Target::Named("libpv3d_zones".into())
}

fn names(reply: &framework::query::Reply) -> Vec<String> {
    reply
        .body
        .children
        .iter()
        .filter_map(|z| z.attr("name").map(str::to_string))
        .collect()
}

#[test]
fn which_zone_contains_a_point_or_an_object() {
    let mut w = harness();
    let mut person = Object3D::new("person 3");
    person.tags = vec!["person".into()];
    person.transform = Affine3A::from_translation(Vec3::new(0.5, 0.5, 0.0));
    w.scene.add(person);
    let mut zones = w.make(zones_config()).unwrap();
    let mut ctx = w.ctx_without_device();

    let at = |x: f32, y: f32| {
        Query::new(to(), "which zone")
            .with_child(XmlElement::new("point").with_attr("x", x).with_attr("y", y))
    };
    let both = zones.answer(&at(1.5, 1.5), &mut ctx).unwrap();
    assert!(both.is_done());
    assert_eq!(names(&both), ["keep out", "stairs"]);
    assert!(names(&zones.answer(&at(9.0, 9.0), &mut ctx).unwrap()).is_empty());

    let person = Query::new(to(), "which zone").with_attr("object", "person 3");
    assert_eq!(
        names(&zones.answer(&person, &mut ctx).unwrap()),
        ["keep out"]
    );

    let ghost = Query::new(to(), "which zone").with_attr("robot", "robot9");
    let reply = zones.answer(&ghost, &mut ctx).unwrap();
    assert_eq!(reply.error, FAILED);
    assert!(reply.body.text.contains("robot9"), "{:?}", reply.body);

    let half = Query::new(to(), "which zone").with_attr("x", 1);
    let reply = zones.answer(&half, &mut ctx).unwrap();
    assert_eq!(reply.error, BAD_ARGUMENTS);
    assert!(
        reply.body.text.contains("no y attribute"),
        "{:?}",
        reply.body
    );

    assert!(zones.answer(&Query::new(to(), "dance"), &mut ctx).is_none());
}

#[test]
fn where_is_a_zone_answers_its_centre_and_names_the_zones_when_unknown() {
    let mut w = harness();
    let mut zones = w.make(zones_config()).unwrap();
    let mut ctx = w.ctx_without_device();
    let stairs = Query::new(to(), "where is").with_attr("zone", "stairs");
    let reply = zones.answer(&stairs, &mut ctx).unwrap();
    assert!(reply.is_done(), "{reply:?}");
    assert_eq!(
        (reply.body.number("x"), reply.body.number("y")),
        (Ok(2.0), Ok(2.0))
    );
    let attic = Query::new(to(), "where is").with_attr("zone", "attic");
    let reply = zones.answer(&attic, &mut ctx).unwrap();
    assert_eq!(reply.error, FAILED);
    assert!(
        reply.body.text.contains("attic") && reply.body.text.contains("keep out, stairs"),
        "{:?}",
        reply.body
    );
    let bare = zones
        .answer(&Query::new(to(), "where is"), &mut ctx)
        .unwrap();
    assert_eq!(bare.error, BAD_ARGUMENTS);
}

//! The localize plugin fed known estimates: the best hypothesis is drawn inside its 95 %
//! ellipse, particles come on request, and a drag on the ground, with the plugin active,
//! becomes a set-pose request with the hand-placed spread.

mod support;

use framework::PluginConfig;
use framework::config::{DeviceRef, Param};
use framework::plugin::{Handled, InputEvent, Plugin};
use glam::Vec3;
use player_proto::body_kind::DataBody;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::localize::{
    Localize, LocalizeData, LocalizeHypothesis, LocalizeParticle, LocalizeParticles, cov,
};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::{Harness, harness};

fn addr() -> DevAddr {
    "localize:0".parse().unwrap()
}

fn config(params: Vec<Param>) -> PluginConfig {
    PluginConfig {
        library: "libpv3d_localize".into(),
        id: "amcl".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: addr(),
            driver: "amcl".into(),
        }),
        params,
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    }
}

fn hypothesis(x: f64, y: f64, alpha: f64, variance: f64) -> LocalizeHypothesis {
    let mut c = [0.0; 6];
    c[cov::XX] = variance;
    c[cov::YY] = variance;
    LocalizeHypothesis {
        mean: Pose2d::new(x, y, 0.0),
        cov: c,
        alpha,
    }
}

fn feed(h: &Harness, hypoths: Vec<LocalizeHypothesis>) {
    let data = LocalizeData {
        hypoths,
        ..LocalizeData::default()
    };
    h.device.push(Message::typed(
        addr(),
        MsgType::Data,
        Localize::Hypotheses(data),
    ));
}

fn make(h: &mut Harness) -> Box<dyn Plugin> {
    h.make(config(vec![])).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn the_best_hypothesis_is_an_arrow_in_its_95_percent_ellipse() {
    let mut h = harness();
    let mut plugin = make(&mut h);
    // Best at (2, 1) with σ = 0.1 m; a faint second one far away.
    feed(
        &h,
        vec![
            hypothesis(-3.0, 0.0, 0.3, 0.5),
            hypothesis(2.0, 1.0, 0.7, 0.01),
        ],
    );
    assert!(h.run_changes_scene(plugin.as_mut()));
    let node = h.scene.get(plugin.node().unwrap()).unwrap();
    assert_eq!(node.geometry.labels[0].text, "70 %");
    let centre = Vec3::new(2.0, 1.0, 0.0);
    // The filled ellipse and the arrow are the only triangles, all about the best mean: the
    // arrow's tip 0.3 m ahead, the fill reaching √5.99 σ ≈ 0.245 m.
    let g = &node.geometry;
    let arrow = g.triangles.iter().map(|v| v.pos);
    let fill: Vec<Vec3> = (g.fans.iter())
        .flat_map(|f| f.fill_triangles().flatten())
        .collect();
    assert!(g.fans.iter().all(|f| f.fill.unwrap().0[3] < 255));
    let reach = (arrow.chain(fill.iter().copied()))
        .map(|p| (p - centre).truncate().length())
        .fold(0.0, f32::max);
    assert!((reach - 0.3).abs() < 1e-3, "{reach}");
    let furthest_fill = (fill.iter())
        .map(|p| (*p - centre).truncate().length())
        .fold(0.0, f32::max);
    assert!((furthest_fill - 0.2448).abs() < 0.001, "{furthest_fill}");
    // The other hypothesis is an outline around (−3, 0) of radius √5.99 · √0.5 ≈ 1.73 m.
    let far = node
        .geometry
        .lines
        .iter()
        .map(|v| (v.pos - Vec3::new(-3.0, 0.0, 0.0)).truncate().length())
        .filter(|d| *d < 2.5)
        .fold(0.0, f32::max);
    assert!((far - 1.7308).abs() < 0.01, "{far}");
    assert!(
        !h.run_changes_scene(plugin.as_mut()),
        "the same estimate twice"
    );
}

#[test]
fn a_drag_on_the_ground_sets_the_pose_while_active_only() {
    let mut h = harness();
    let mut plugin = make(&mut h);
    let click = InputEvent::GroundClicked(Vec3::new(1.0, 3.0, 0.0));
    assert_eq!(plugin.on_event(&click, &mut h.ctx()), Handled::No);
    assert!(h.device.requests.lock().unwrap().is_empty(), "not active");

    assert!(plugin.can_be_active());
    plugin.on_event(&InputEvent::Activated(true), &mut h.ctx());
    for at in [Vec3::new(1.0, 1.0, 0.0), Vec3::new(1.0, 2.0, 0.0)] {
        assert_eq!(
            plugin.on_event(&InputEvent::TargetDragged(at), &mut h.ctx()),
            Handled::Yes
        );
    }
    let preview = h.scene.get(plugin.node().unwrap()).unwrap();
    assert!(
        !preview.geometry.lines.is_empty(),
        "the pose being given shows"
    );
    assert_eq!(plugin.on_event(&click, &mut h.ctx()), Handled::Yes);

    let requests = h.device.requests.lock().unwrap();
    assert_eq!(requests.len(), 1);
    let (kind, body) = &requests[0];
    assert_eq!(*kind, Localize::REQ_SET_POSE.kind());
    let sent = Localize::REQ_SET_POSE
        .body_of(body)
        .expect("a set-pose body");
    assert_eq!(
        (sent.mean.px, sent.mean.py),
        (1.0, 1.0),
        "where the press was"
    );
    assert!((sent.mean.pa - std::f64::consts::FRAC_PI_2).abs() < 1e-6);
    assert_eq!(sent.cov[cov::XX], 0.25, "the default 0.5 m spread");
    assert!((sent.cov[cov::AA] - 15f64.to_radians().powi(2)).abs() < 1e-12);
}

#[test]
fn particles_are_asked_for_and_drawn_as_points() {
    let mut h = harness();
    let mut plugin = make(&mut h);
    let names: Vec<_> = plugin.services().iter().map(|s| s.name).collect();
    assert_eq!(names, ["Show particles"]);
    plugin.run_service("Show particles", &mut h.ctx());
    let asked = h.device.requests.lock().unwrap().len();
    assert_eq!(asked, 1);
    let cloud = LocalizeParticles {
        particles: (0..5)
            .map(|i| LocalizeParticle {
                pose: Pose2d::new(f64::from(i), 0.0, 0.0),
                alpha: 0.2,
            })
            .collect(),
        ..LocalizeParticles::default()
    };
    let reply = Message::typed(addr(), MsgType::Ack, Localize::Particles(cloud));
    assert_eq!(
        h.device
            .answer_later(Localize::REQ_GET_PARTICLES.kind(), Ok(reply)),
        1
    );
    plugin.run(&mut h.ctx());
    let points = h
        .scene
        .iter()
        .find(|(_, o)| o.name.ends_with("particles"))
        .map(|(_, o)| o.geometry.points.len());
    assert_eq!(points, Some(5));
    assert_eq!(plugin.save().param("showParticles").unwrap().text, "1");
    plugin.run_service("Hide particles", &mut h.ctx());
    assert!(h.scene.iter().all(|(_, o)| o.geometry.points.is_empty()));
}

#[test]
fn a_spread_out_of_range_names_the_parameter() {
    let mut h = harness();
    let error = h
        .make(config(vec![Param::new("headingStdDev", "400")]))
        .err()
        .expect("400° refused");
    assert!(error.to_string().contains("headingStdDev"), "{error}");
}

/// The text beside the best hypothesis once `hypoths` has been drawn.
fn label_for(hypoths: Vec<LocalizeHypothesis>) -> String {
    let mut h = harness();
    let mut plugin = make(&mut h);
    feed(&h, hypoths);
    assert!(h.run_changes_scene(plugin.as_mut()));
    let node = h.scene.get(plugin.node().unwrap()).unwrap();
    assert_eq!(node.geometry.labels.len(), 1, "one label, the best's");
    node.geometry.labels[0].text.clone()
}

#[test]
fn a_weight_is_shown_as_its_share_of_the_message_whatever_its_scale() {
    // fakelocalize's constant beside a weightless hypothesis: all of it, not "100000000 %".
    assert_eq!(
        label_for(vec![
            hypothesis(1.0, 1.0, 1e6, 0.01),
            hypothesis(4.0, 0.0, 0.0, 0.01)
        ]),
        "100 %"
    );
    // Weights on any scale share out alike.
    assert_eq!(
        label_for(vec![
            hypothesis(1.0, 1.0, 30.0, 0.01),
            hypothesis(4.0, 0.0, 10.0, 0.01)
        ]),
        "75 %"
    );
    // One hypothesis alone has no meaningful share, whatever weight it carries.
    assert_eq!(
        label_for(vec![hypothesis(1.0, 1.0, 1e6, 0.01)]),
        "sole hypothesis"
    );
}

#[test]
fn unusable_weights_fall_back_quietly() {
    // A NaN and a negative weight: the usable one is best, and no share is made up.
    let label = label_for(vec![
        hypothesis(-2.0, 0.0, f64::NAN, 0.01),
        hypothesis(1.0, 1.0, 0.2, 0.01),
        hypothesis(3.0, 0.0, -1.0, 0.01),
    ]);
    assert_eq!(label, "share unknown");
    let mut h = harness();
    let mut plugin = make(&mut h);
    feed(
        &h,
        vec![
            hypothesis(-2.0, 0.0, f64::NAN, 0.01),
            hypothesis(1.0, 1.0, 0.2, 0.01),
        ],
    );
    assert!(h.run_changes_scene(plugin.as_mut()));
    let node = h.scene.get(plugin.node().unwrap()).unwrap();
    let best_at = node.geometry.labels[0].pos - Vec3::new(0.3, 0.3, 0.0);
    assert!(
        (best_at.truncate() - glam::Vec2::new(1.0, 1.0)).length() < 1e-5,
        "the label sits by the usable hypothesis, not the NaN one: {best_at}"
    );
    // All weights unusable or zero: still drawn, still no percentage.
    assert_eq!(
        label_for(vec![
            hypothesis(0.0, 0.0, f64::INFINITY, 0.01),
            hypothesis(1.0, 0.0, -3.0, 0.01)
        ]),
        "share unknown"
    );
    assert_eq!(
        label_for(vec![
            hypothesis(0.0, 0.0, 0.0, 0.01),
            hypothesis(1.0, 0.0, 0.0, 0.01)
        ]),
        "share unknown"
    );
}

/// Every `PLAYER_LOCALIZE_DATA_HYPOTHS` real amcl sent in `captures/nav/`.
fn amcl_estimates() -> Vec<Message> {
    support::captured_messages("nav/localize_hypotheses_setpose.jsonl")
        .into_iter()
        .filter(|m| LocalizeData::KIND.of(m).is_some())
        .collect()
}

#[test]
fn real_amcl_estimates_are_labelled_without_a_made_up_share() {
    let estimates = amcl_estimates();
    assert_eq!(estimates.len(), 10, "the capture's ten estimates");
    let mut h = harness();
    let mut plugin = make(&mut h);
    for message in estimates {
        // Drawn as sent to the plugin's own device.
        let mut message = message;
        message.header.addr = addr();
        h.device.push(message);
        assert!(h.run_changes_scene(plugin.as_mut()));
        let node = h.scene.get(plugin.node().unwrap()).unwrap();
        // amcl sends one hypothesis holding weight 1: a share of one says nothing.
        assert_eq!(node.geometry.labels[0].text, "sole hypothesis");
    }
}

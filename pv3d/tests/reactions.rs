//! Queries through the viewer and reactions to awareness events: a walker (a test plugin
//! moving a `person`-tagged object) crosses a zone; the viewer asks the zones where it is,
//! and the composition's reactions stop the robot (a query), say a sentence and load a
//! component.

use std::cell::RefCell;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Instant;

use framework::query::{Query, QueryError, Reply, Target, XmlElement};
use framework::registry::Metadata;
use framework::scene::{NodeId, Object3D};
use framework::{ConfigValueError, Plugin, PluginConfig, PluginContext};
use glam::{Affine3A, Vec3};
use pv3d::app::Viewer;
use pv3d::composition::{PluginInstance, parse_str};

thread_local! {
    /// Queries the test robot was asked, by name (per test: each runs on its own thread).
    static ASKED: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
}

fn asked() -> Vec<String> {
    ASKED.with(|a| a.borrow().clone())
}

const TEST: Metadata = Metadata {
    author: "pv3d tests",
    email: "tests@example.invalid",
    web_page: "https://example.invalid/reactions",
    description: "A test component.",
};

/// A person walking along x, 0.5 m each update, from x = -2.
struct Walker {
    config: PluginConfig,
    node: NodeId,
    x: f32,
}

impl Walker {
    fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let mut person = Object3D::new("walker");
        person.tags = vec!["person".into()];
        let node = ctx.scene.add(person);
        Ok(Box::new(Walker {
            config,
            node,
            x: -2.0,
        }))
    }
}

impl Plugin for Walker {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }
    fn title(&self) -> String {
        "walker".into()
    }
    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.x += 0.5;
        if let Some(o) = ctx.scene.get_mut(self.node) {
            o.transform = Affine3A::from_translation(Vec3::new(self.x, 0.0, 0.0));
            // Tired from x = 0 until x = 1: a condition, as a robot's `stalled`.
            o.tags.retain(|t| t != "tired");
            if (0.0..1.0).contains(&self.x) {
                o.tags.push("tired".into());
            }
        }
    }
    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}

/// A robot that writes down what it is asked and answers "stop".
struct Robot(PluginConfig);

impl Robot {
    fn create(
        config: PluginConfig,
        _ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        Ok(Box::new(Robot(config)))
    }
}

impl Plugin for Robot {
    fn save(&self) -> PluginConfig {
        self.0.clone()
    }
    fn title(&self) -> String {
        "robot".into()
    }
    fn answer(&mut self, query: &Query, _ctx: &mut PluginContext<'_>) -> Option<Reply> {
        ASKED.with(|a| a.borrow_mut().push(query.name.clone()));
        query
            .is("stop")
            .then(|| Reply::done(XmlElement::new("stopped")))
    }
    fn clean(&mut self, _ctx: &mut PluginContext<'_>) {}
}

fn instance(xml: &str) -> PluginInstance {
    PluginInstance {
        element: parse_str(xml, Arc::new(PathBuf::from("aware.xml"))).unwrap(),
        device: None,
    }
}

fn viewer() -> Viewer {
    let mut registry = plugins::standard_plugins();
    registry.register("libpv3d_walker", TEST, Walker::create);
    registry.register("libpv3d_testrobot", TEST, Robot::create);
    let instances = vec![
        instance(r#"<plugin library="libpv3d_testrobot" id="robot1"/>"#),
        instance(r#"<plugin library="libpv3d_walker" id="walker"/>"#),
        instance(
            r#"<plugin library="libpv3d_zones" id="zones">
                 <zone name="keep out">-0.5 -1  0.5 -1  0.5 1  -0.5 1</zone>
               </plugin>"#,
        ),
        instance(
            r#"<plugin library="libpv3d_reactions">
                 <reaction on="enter" zone="keep out" tag="person|robot">
                   <query to="robot1">stop</query>
                   <say>Someone is in the keep-out area.</say>
                   <load><plugin library="libpv3d_grid" id="alarm"/></load>
                 </reaction>
                 <reaction on="exit" zone="keep out" tag="person">
                   <say>Clear.</say>
                 </reaction>
                 <reaction on="appear" tag="person"><say>Hello.</say></reaction>
                 <reaction on="tagged" tag="tired"><say>Tired.</say></reaction>
                 <reaction on="untagged" tag="tired"><say>Rested.</say></reaction>
               </plugin>"#,
        ),
    ];
    let viewer = Viewer::new(instances, registry, &|_| None);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    viewer
}

#[test]
fn a_person_walking_into_a_zone_fires_its_reactions() {
    let mut viewer = viewer();
    let plugins_before = viewer.plugin_count();
    // x: -1.5, -1.0, -0.5 (on the edge), 0.0 (inside), 0.5, 1.0 (out).
    let mut said_at = Vec::new();
    for step in 0..6 {
        viewer.update(Instant::now());
        said_at.push((step, viewer.reactions().said.clone()));
    }
    let said = &viewer.reactions().said;
    assert_eq!(
        said.first().map(String::as_str),
        Some("Hello."),
        "{said_at:?}"
    );
    assert!(
        said.contains(&"Someone is in the keep-out area.".to_string()),
        "{said_at:?}"
    );
    assert_eq!(
        said.iter().filter(|s| s.starts_with("Someone")).count(),
        1,
        "entered once: {said:?}"
    );
    let at = |s: &str| said.iter().position(|x| x == s);
    assert!(
        at("Clear.") > at("Someone is in the keep-out area."),
        "{said:?}"
    );
    assert!(
        at("Tired.").is_some() && at("Tired.") < at("Rested."),
        "{said:?}"
    );
    assert_eq!(
        said.iter().filter(|s| *s == "Tired.").count(),
        1,
        "{said:?}"
    );
    assert_eq!(asked(), ["stop"], "the reaction's query reached robot1");
    assert_eq!(
        viewer.plugin_count(),
        plugins_before + 1,
        "the alarm grid was loaded"
    );
    assert!(
        viewer
            .reactions()
            .fired
            .iter()
            .any(|f| f == "enter walker keep out"),
        "{:?}",
        viewer.reactions().fired
    );
}

#[test]
fn queries_route_through_the_viewer_and_say_who_did_not_answer() {
    let mut viewer = viewer();
    viewer.update(Instant::now());
    let where_is =
        Query::parse(r#"<query to="libpv3d_zones" name="which zone" object="walker"/>"#).unwrap();
    let reply = viewer.ask(&where_is).unwrap();
    assert!(
        reply.body.children.is_empty(),
        "at x = -1.5, in no zone: {reply:?}"
    );

    let any = Query::parse(r#"<query to="world" name="is there any" tag="person"/>"#).unwrap();
    assert_eq!(viewer.ask(&any).unwrap().body.attr("count"), Some("1"));

    let dance = Query::parse(r#"<query to="robot1">dance</query>"#).unwrap();
    let err = viewer.ask(&dance).unwrap_err();
    assert!(matches!(err, QueryError::Unanswered { .. }), "{err}");
    assert!(
        err.to_string().contains("dance") && err.to_string().contains("robot1"),
        "{err}"
    );

    // Typed or scripted as XML, a query is sent as written.
    assert_eq!(
        viewer.command(r#"<query to="robot1">stop</query>"#),
        Ok(r#"<reply error="0"><stopped/></reply>"#.to_string())
    );
    let torn = viewer.command(r#"<query to="robot1">stop"#).unwrap_err();
    assert!(torn.contains("1:"), "names where: {torn}");

    let nobody = Query::new(Target::Named("robot9".into()), "stop");
    assert!(matches!(
        viewer.ask(&nobody),
        Err(QueryError::NoSuchComponent { .. })
    ));
}

#[test]
fn a_bad_reaction_is_an_error_naming_where() {
    let instances = vec![instance(
        "<plugin library=\"libpv3d_reactions\">\n  <reaction on=\"explode\"><say>x</say></reaction>\n</plugin>",
    )];
    let viewer = Viewer::new(instances, plugins::standard_plugins(), &|_| None);
    assert_eq!(viewer.errors.len(), 1);
    assert!(
        viewer.errors[0].contains("aware.xml:2:"),
        "{:?}",
        viewer.errors
    );
    assert!(viewer.errors[0].contains("explode"), "{:?}", viewer.errors);
}

#[test]
fn a_reaction_commands_in_words_and_loads_only_what_a_device_fits() {
    let mut registry = plugins::standard_plugins();
    registry.register("libpv3d_walker", TEST, Walker::create);
    let instances = vec![
        instance(r#"<plugin library="libpv3d_walker" id="walker"/>"#),
        instance(
            r#"<plugin library="libpv3d_reactions">
                 <reaction on="appear" tag="person">
                   <command>all robots stop</command>
                   <load>
                     <plugin library="libpv3d_laser" id="watch">
                       <playerDeviceMask interface="laser"/>
                     </plugin>
                   </load>
                 </reaction>
               </plugin>"#,
        ),
    ];
    let mut viewer = Viewer::new(instances, registry, &|_| None);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    let before = viewer.plugin_count();
    viewer.update(Instant::now());
    // The sentence went through the grammar and the executor, as a typed one does.
    assert_eq!(
        viewer.replies(),
        [Err(
            "all robots stop: there is no robot to command".to_string()
        )]
    );
    // No server lists a laser: the watch is reported where it was written, not made blind.
    assert_eq!(viewer.plugin_count(), before);
    assert!(
        viewer
            .errors
            .iter()
            .any(|e| e.starts_with("aware.xml:") && e.contains("no device listed now fits")),
        "{:?}",
        viewer.errors
    );
}

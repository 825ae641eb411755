//! A component asks another through the viewer: the query sent in `run` is routed after it,
//! and the reply comes back to the sender's `on_reply` in the same update.

use std::cell::RefCell;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Instant;

use framework::query::{Query, QueryError, Reply, Target, XmlElement};
use framework::registry::Metadata;
use framework::{ConfigValueError, Plugin, PluginConfig, PluginContext};
use pv3d::app::Viewer;
use pv3d::composition::{PluginInstance, parse_str};

thread_local! {
    /// What the asker got back, per test thread.
    static REPLIES: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
}

const TEST: Metadata = Metadata {
    author: "pv3d tests",
    email: "tests@example.invalid",
    web_page: "https://example.invalid/queries",
    description: "A test component.",
};

/// Asks the zones about the origin, and a robot nobody has, on its first run.
struct Asker(PluginConfig, bool);

impl Plugin for Asker {
    fn save(&self) -> PluginConfig {
        self.0.clone()
    }
    fn title(&self) -> String {
        "asker".into()
    }
    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        if std::mem::replace(&mut self.1, true) {
            return;
        }
        let origin = XmlElement::new("point").with_attr("x", 0).with_attr("y", 0);
        assert!(
            ctx.send(Query::new(Target::Named("zones".into()), "which zone").with_child(origin))
        );
        assert!(ctx.send(Query::new(Target::Named("robot9".into()), "stop")));
    }
    fn on_reply(
        &mut self,
        _q: &Query,
        result: &Result<Reply, QueryError>,
        _ctx: &mut PluginContext<'_>,
    ) {
        let text = match result {
            Ok(reply) => reply.to_xml(),
            Err(e) => e.to_string(),
        };
        REPLIES.with(|r| r.borrow_mut().push(text));
    }
    fn clean(&mut self, _ctx: &mut PluginContext<'_>) {}
}

fn instance(xml: &str) -> PluginInstance {
    PluginInstance {
        element: parse_str(xml, Arc::new(PathBuf::from("ask.xml"))).unwrap(),
        device: None,
    }
}

#[test]
fn a_plugin_asks_another_and_gets_the_reply() {
    let mut registry = plugins::standard_plugins();
    let create = |config, _: &mut PluginContext<'_>| -> Result<Box<dyn Plugin>, ConfigValueError> {
        Ok(Box::new(Asker(config, false)))
    };
    registry.register("libpv3d_asker", TEST, create);
    let instances = vec![
        instance(r#"<plugin library="libpv3d_asker" id="asker"/>"#),
        instance(
            r#"<plugin library="libpv3d_zones" id="zones"><zone name="hall">-1 -1  1 -1  1 1  -1 1</zone></plugin>"#,
        ),
    ];
    let mut viewer = Viewer::new(instances, registry, &|_| None);
    viewer.update(Instant::now());
    let replies = REPLIES.with(|r| r.borrow().clone());
    assert_eq!(replies.len(), 2, "{replies:?}");
    assert!(replies[0].contains(r#"<zone name="hall"/>"#), "{replies:?}");
    assert!(
        replies[1].contains("robot9") && replies[1].contains("no component"),
        "{replies:?}"
    );
}

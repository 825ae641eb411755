//! The component lifecycle as the viewer drives it: each plugin is initialized once, before
//! its first run, also when it is added later; run on every iteration; cleaned when the viewer
//! goes — and nothing is called on it after that.

use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::Instant;

use framework::registry::Metadata;
use framework::scene::{NodeId, Object3D};
use framework::{ConfigValueError, Plugin, PluginConfig, PluginContext, PluginRegistry};
use pv3d::app::Viewer;
use pv3d::composition::{PluginInstance, parse_str};

/// What the recording plugins saw, in order, as "id: call".
static CALLS: Mutex<Vec<String>> = Mutex::new(Vec::new());

fn record(id: &str, call: &str) {
    CALLS.lock().unwrap().push(format!("{id}: {call}"));
}

fn calls() -> Vec<String> {
    std::mem::take(&mut *CALLS.lock().unwrap())
}

/// A plugin that only writes down what is called on it.
struct Recorder {
    config: PluginConfig,
    node: NodeId,
}

impl Recorder {
    const METADATA: Metadata = Metadata {
        author: "pv3d tests",
        email: "tests@example.invalid",
        web_page: "https://example.invalid/recorder",
        description: "Writes down the lifecycle calls it gets.",
    };

    fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        record(&config.id, "made");
        let node = ctx.scene.add(Object3D::new(config.id.clone()));
        Ok(Box::new(Recorder { config, node }))
    }
}

impl Plugin for Recorder {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        self.config.id.clone()
    }

    fn initialize(&mut self, _ctx: &mut PluginContext<'_>) {
        record(&self.config.id, "initialize");
    }

    fn run(&mut self, _ctx: &mut PluginContext<'_>) {
        record(&self.config.id, "run");
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        record(&self.config.id, "clean");
        ctx.scene.remove(self.node);
    }
}

fn instance(id: &str) -> PluginInstance {
    let text = format!(r#"<plugin library="librecorder" id="{id}"/>"#);
    let element = parse_str(&text, Arc::new(PathBuf::from("lifecycle.xml"))).unwrap();
    PluginInstance {
        element,
        device: None,
    }
}

#[test]
fn plugins_are_initialized_once_run_each_iteration_and_cleaned_last() {
    let mut registry = PluginRegistry::default();
    registry.register("librecorder", Recorder::METADATA, Recorder::create);
    let mut viewer = Viewer::new(vec![instance("a")], registry, &|_| None);
    assert_eq!(
        calls(),
        ["a: made"],
        "made, not yet initialized: no frame yet"
    );

    viewer.update(Instant::now());
    viewer.update(Instant::now());
    assert_eq!(calls(), ["a: initialize", "a: run", "a: run"]);

    // A plugin added later (a server that answered late) gets its own initialize.
    viewer.add_plugins(vec![instance("b")], &|_| None);
    viewer.update(Instant::now());
    assert_eq!(calls(), ["b: made", "a: run", "b: initialize", "b: run"]);

    let nodes = |v: &Viewer| v.scene().iter().count();
    assert_eq!(nodes(&viewer), 2);
    drop(viewer);
    let mut last = calls();
    last.sort();
    assert_eq!(last, ["a: clean", "b: clean"], "cleaned on the way out");
}

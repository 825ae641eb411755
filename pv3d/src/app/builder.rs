//! Making a viewer from a composition: a client for every Player server, the composer that
//! turns the handlers into plugin instances for the devices each server reports, the standard
//! plugins, and the wake-up of a window when a server answers. `pv3d` and the integration tests
//! both build their viewer here, so that a test runs the viewer the program runs.

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use player_proto::client::Notifier;

use super::viewer::{SaveTarget, Viewer};
use crate::composition::Composer;
use crate::composition::{Composition, PluginInstance};
use crate::render::Projection;
use crate::robots::{RobotManager, RobotOptions};

/// What the viewer is built from, and how.
pub struct ViewerBuilder {
    composition: Composition,
    wake: Option<Notifier>,
    connect_timeout: Duration,
    projection: Projection,
    save_to: Option<PathBuf>,
    robot_options: RobotOptions,
}

impl ViewerBuilder {
    /// A viewer of `composition` in the top view, with nothing to wake and no file to save to;
    /// it waits up to 3 s for the servers' device lists.
    pub fn new(composition: Composition) -> ViewerBuilder {
        ViewerBuilder {
            composition,
            wake: None,
            connect_timeout: Duration::from_secs(3),
            projection: Projection::Top,
            save_to: None,
            robot_options: RobotOptions::default(),
        }
    }

    /// Every message of every connection shown to `tap` (`--record`).
    pub fn record_with(mut self, tap: Option<player_proto::client::Tap>) -> ViewerBuilder {
        self.robot_options.tap = tap;
        self
    }

    /// Watch only (`--observe`): read-only clients, no tele-operation.
    pub fn observe(mut self, observe: bool) -> ViewerBuilder {
        self.robot_options.observe = observe;
        self
    }

    /// Called from the servers' threads whenever there is something new to draw: data, or a
    /// server that answered (see [`super::UiWaker::notifier`]).
    pub fn wake_with(mut self, wake: Notifier) -> ViewerBuilder {
        self.wake = Some(wake);
        self
    }

    /// How long [`ViewerBuilder::connect`] waits for the servers' device lists. A server that
    /// answers later gets its plugins when it answers.
    pub fn connect_timeout(mut self, timeout: Duration) -> ViewerBuilder {
        self.connect_timeout = timeout;
        self
    }

    /// The projection the 3D view starts in.
    pub fn start_view(mut self, projection: Projection) -> ViewerBuilder {
        self.projection = projection;
        self
    }

    /// Where "Save" (and quitting) writes the composition with the plugins' current state.
    pub fn save_to(mut self, path: PathBuf) -> ViewerBuilder {
        self.save_to = Some(path);
        self
    }

    /// Starts a client for every server and waits, at most the connect timeout, for their
    /// handshakes; the plugin instances are made for the devices of the servers that answered.
    pub fn connect(self) -> ViewerParts {
        let robots = Arc::new(RobotManager::start_with(
            &self.composition.clients,
            self.wake.clone(),
            self.robot_options.clone(),
        ));
        robots.wait_for_handshakes(self.connect_timeout);
        let mut composer = Composer::new(self.composition.clone());
        let instances = composer.initial(&robots);
        ViewerParts {
            builder: self,
            robots,
            composer,
            instances,
        }
    }

    /// [`ViewerBuilder::connect`], then [`ViewerParts::into_viewer`].
    pub fn build(self) -> Viewer {
        self.connect().into_viewer()
    }
}

/// A composition whose servers were asked for their devices: the plugin instances to make,
/// before they are made (`--emit-config` writes them out instead).
pub struct ViewerParts {
    builder: ViewerBuilder,
    robots: Arc<RobotManager>,
    composer: Composer,
    /// One per plugin to make: those named outright, and the handlers' for every device of
    /// the servers that answered.
    pub instances: Vec<PluginInstance>,
}

impl ViewerParts {
    pub fn composition(&self) -> &Composition {
        &self.builder.composition
    }

    /// Makes the plugins, from the standard ones. A composition with no servers gets no
    /// server status panel and nothing that waits for servers.
    /// What `--emit-config` writes: the instances made, and the plugins named outright that
    /// still wait for their device's server (so the written file keeps them).
    pub fn written_instances(&self) -> Vec<PluginInstance> {
        let mut written = self.instances.clone();
        written.extend(self.composer.waiting().iter().cloned());
        written
    }

    /// The robots' clients (`--serve-web` names them to its page, so that a command from it is
    /// answered with the page's rule rather than "no such robot").
    pub fn clients(&self) -> impl Iterator<Item = &Arc<player_proto::client::Client>> {
        self.robots.clients().map(|(_, _, client)| client)
    }

    pub fn into_viewer(self) -> Viewer {
        let ViewerParts {
            builder,
            robots,
            composer,
            instances,
        } = self;
        let lookup = robots.clone();
        let mut viewer = Viewer::new(instances, plugins::standard_plugins(), &|device| {
            lookup.device(device)
        });
        viewer.view.camera.projection = builder.projection;
        if !builder.composition.clients.is_empty() {
            viewer.robots = Some(robots);
            viewer.composer = Some(composer);
        }
        viewer.save_target = builder.save_to.map(|path| SaveTarget {
            path,
            composition: builder.composition,
        });
        viewer
    }
}

//! The publishing side: a relay front ([`ZenohFront::robot_tap`] goes in the relay's `fronts`)
//! that puts every robot of the relay into Zenoh under `player/<site>/<robot>/…` (see
//! [`crate::keys`]), answers the `devices` and `replies` queryables from what it saw, keeps a
//! liveliness token per connected robot, and passes commands from the one authorised
//! controller to the robot's upstream client.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use player_front::{Front, FrontRuntime, Watch, Watching};
use player_proto::RobotId;
use player_proto::capture::Direction;
use player_proto::client::{Client, ConnectionTap, RobotTap, Tap, TapEvent, unnamed};
use player_proto::wire::MsgType;
use tokio::runtime::Handle;
use zenoh::Session;
use zenoh::Wait;
use zenoh::pubsub::Subscriber;
use zenoh::query::Queryable;

use crate::error::ZenohError;
use crate::keys::RobotKey;
use crate::queue::{EventQueue, FrontEvent};
use crate::shared::{FrontConfig, FrontShared};

/// A running front; stops publishing, and withdraws its robots, when dropped.
pub struct ZenohFront {
    shared: Arc<FrontShared>,
    runtime: FrontRuntime,
    _commands: Subscriber<()>,
    _queryables: Vec<Queryable<()>>,
}

impl ZenohFront {
    /// Starts publishing on `session`, on a runtime of its own; robots appear as the relay's
    /// taps report them.
    pub fn start(session: Session, config: FrontConfig) -> Result<ZenohFront, ZenohError> {
        let runtime = FrontRuntime::own("zenoh-front", 1)?;
        ZenohFront::publish(runtime, session, config)
    }

    /// As [`ZenohFront::start`], on the runtime of `handle` (the relay's for all its fronts):
    /// dropping the front ends its publisher and leaves that runtime running.
    pub fn start_on(
        handle: Handle,
        session: Session,
        config: FrontConfig,
    ) -> Result<ZenohFront, ZenohError> {
        ZenohFront::publish(FrontRuntime::on(handle), session, config)
    }

    fn publish(
        runtime: FrontRuntime,
        session: Session,
        config: FrontConfig,
    ) -> Result<ZenohFront, ZenohError> {
        let shared = Arc::new(FrontShared {
            queue: EventQueue::new(config.queue),
            config,
            session,
            robots: Mutex::new(HashMap::new()),
            looks: Mutex::new(HashMap::new()),
            runtime: runtime.handle().clone(),
            refused: AtomicU64::new(0),
        });
        runtime.spawn(crate::publish::run(shared.clone()));
        let commands = crate::commands::declare_commands(&shared)?;
        let queryables = vec![
            crate::commands::declare_requests(&shared)?,
            crate::answers::declare_devices(&shared)?,
            crate::answers::declare_replies(&shared)?,
        ];
        tracing::info!(site = %shared.config.site, controller = ?shared.config.controller,
            "publishing the relay's robots in Zenoh");
        Ok(ZenohFront {
            shared,
            runtime,
            _commands: commands,
            _queryables: queryables,
        })
    }

    /// The tap to put in `RelayConfig::fronts`: each robot keyed by its name where it has one
    /// ([`RobotKey::of_robot`]).
    pub fn robot_tap(&self) -> RobotTap {
        let shared = self.shared.clone();
        Arc::new(move |robot: &RobotId| -> ConnectionTap {
            let robot = RobotKey::of_robot(&shared.config.site, robot);
            let shared = shared.clone();
            Arc::new(move |time, event| {
                let event = match event {
                    TapEvent::Opened(_) => FrontEvent::Opened(robot.clone()),
                    TapEvent::Closed(why) => FrontEvent::Closed(robot.clone(), why.into()),
                    TapEvent::Frame {
                        direction,
                        header,
                        body,
                    } => {
                        // Only requests matter of what the relay sends: their replies are
                        // paired with them in the cache.
                        if direction == Direction::ClientToServer && header.msg_type != MsgType::Req
                        {
                            return;
                        }
                        // Data no Zenoh subscriber matches (another front's, an observer's)
                        // is not queued.
                        if header.msg_type == MsgType::Data
                            && !shared.looked_at(&robot, (header.addr.interf, header.addr.index))
                        {
                            return;
                        }
                        FrontEvent::Frame {
                            robot: robot.clone(),
                            time,
                            direction,
                            header: *header,
                            body: body.clone(),
                        }
                    }
                };
                shared.queue.push(event);
            })
        })
    }

    /// The tap for Player clients that know no names: robots keyed `<host>_<port>`.
    pub fn tap(&self) -> Tap {
        unnamed(self.robot_tap())
    }

    /// Lets commands reach this unnamed robot through its relay client (whose host and port
    /// name it).
    pub fn add_robot(&self, client: Arc<Client>) {
        self.add_robot_as(&RobotId::new(client.host(), client.port()), client);
    }

    /// Lets commands reach the robot `id` through its relay client.
    pub fn add_robot_as(&self, id: &RobotId, client: Arc<Client>) {
        let robot = self.key_of(id);
        self.shared.robots().entry(robot).or_default().client = Some(client);
    }

    /// The key of an unnamed robot of this front.
    pub fn robot_key(&self, host: &str, port: u16) -> RobotKey {
        RobotKey::new(&self.shared.config.site, host, port)
    }

    /// The key of the robot `id` on this front.
    pub fn key_of(&self, id: &RobotId) -> RobotKey {
        RobotKey::of_robot(&self.shared.config.site, id)
    }

    /// DATA messages dropped because Zenoh could not take them fast enough.
    pub fn dropped(&self) -> u64 {
        self.shared.queue.dropped()
    }

    /// Commands and requests refused so far.
    pub fn refused(&self) -> u64 {
        self.shared.refused.load(Ordering::Relaxed)
    }

    /// Devices some Zenoh subscriber matches now, over every robot.
    pub fn looks(&self) -> usize {
        self.shared.looks().len()
    }

    /// Robots announced (connected, described, with a liveliness token) now.
    pub fn announced(&self) -> usize {
        self.shared
            .robots()
            .values()
            .filter(|r| r.token.is_some())
            .count()
    }
}

/// Zenoh as one of the relay's fronts: each robot under its key, commands from the one
/// authorised controller through the relay's clients.
impl Front for ZenohFront {
    fn name(&self) -> &str {
        "Zenoh"
    }

    fn arrived(&self, robot: &RobotId) -> ConnectionTap {
        (self.robot_tap())(robot)
    }

    fn commands_through(&self, robot: &RobotId, client: Arc<Client>) {
        self.add_robot_as(robot, client);
    }

    /// Each device's data key is looked at while a Zenoh subscriber matches it (see
    /// `publish`): the relay subscribes upstream to that alone.
    fn watch(&self, robot: &RobotId, watch: Watch) -> Watching {
        let robot = self.key_of(robot);
        self.shared.robots().entry(robot).or_default().watch = Some(watch);
        Watching::AsLooked
    }
}

impl Drop for ZenohFront {
    fn drop(&mut self) {
        self.runtime.stop();
        let tokens: Vec<_> = self
            .shared
            .robots()
            .values_mut()
            .filter_map(|r| r.token.take())
            .collect();
        for token in tokens {
            let _ = token.undeclare().wait();
        }
    }
}

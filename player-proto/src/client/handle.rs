//! The [`Client`] handle: starting the robot thread, and reading what it publishes.

use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use tokio::sync::mpsc::{UnboundedSender, unbounded_channel};

use super::commands::Command;
use super::options::ClientOptions;
use super::published::{Board, ConnectionState, DeviceInfo, Snapshot};
use super::robot_thread::{self, Robot};
use super::session_state::SessionState;
use super::shared_io::SharedIo;
use super::store::{DataStore, DeviceStats, Stamped};
use super::{ConnectError, DataMode, ReplaceRule};
use crate::wire::{Banner, DevAddr, Interface};

/// A connection to one Player server (one robot, one port).
pub struct Client {
    pub(super) host: String,
    pub(super) port: u16,
    pub(super) options: ClientOptions,
    board: Arc<Board>,
    store: Arc<DataStore>,
    pub(super) commands: UnboundedSender<Command>,
    runner: Option<Runner>,
}

/// What runs the connection: a thread of its own, or a task on shared threads.
enum Runner {
    Thread(JoinHandle<()>),
    /// Disconnected when the task has ended (its sender dropped); in a mutex only so that a
    /// client can be shared between threads.
    Task(std::sync::Mutex<std::sync::mpsc::Receiver<()>>),
}

impl Client {
    /// Starts the robot thread and returns at once; the thread keeps trying to connect (see
    /// [`Client::state`]). Use this when an unreachable robot must not hold anything up.
    pub fn spawn(host: &str, port: u16, options: ClientOptions) -> Result<Client, ConnectError> {
        let board = Arc::new(Board::new(Snapshot::new(options.data_mode)));
        let store = Arc::new(DataStore::default());
        // Made here, so that its data mode and rules are published before this returns; from
        // now on only the thread changes it.
        let session = SessionState::new(&options, board.clone());
        let (commands, receiver) = unbounded_channel();
        let (name, robot_options) = (host.to_string(), options.clone());
        let mut robot = Robot::new(
            name,
            port,
            robot_options,
            session,
            board.clone(),
            store.clone(),
            receiver,
        );
        let runner = match &options.shared_io {
            Some(io) => {
                let (ended, done) = std::sync::mpsc::channel::<()>();
                io.spawn(async move {
                    robot.run().await;
                    drop(ended);
                });
                Runner::Task(std::sync::Mutex::new(done))
            }
            None => Runner::Thread(
                std::thread::Builder::new()
                    .name(format!("player {host}:{port}"))
                    .spawn(move || robot_thread::run(robot))
                    .map_err(|e| ConnectError::Thread(e.to_string()))?,
            ),
        };
        Ok(Client {
            host: host.to_string(),
            port,
            options,
            board,
            store,
            commands,
            runner: Some(runner),
        })
    }

    /// Connects and waits until the handshake is done (device list and driver names known).
    /// Fails if the server cannot be reached within the connect and request timeouts.
    pub fn connect(host: &str, port: u16, options: ClientOptions) -> Result<Client, ConnectError> {
        let limit = options.connect_timeout + options.request_timeout;
        let client = Client::spawn(host, port, options)?;
        let unreachable = |why: String| ConnectError::Unreachable {
            host: host.into(),
            port,
            why,
        };
        match client.wait_for_state(limit, |s| *s != ConnectionState::Connecting) {
            Some(ConnectionState::Connected) => Ok(client),
            Some(ConnectionState::Failed(why)) => Err(unreachable(why)),
            // Retrying: the first attempt's own reason (a name that does not resolve, a
            // refused port, a banner that is not Player's) says more than any summary.
            Some(_) => Err(unreachable(client.last_disconnect().unwrap_or_else(|| {
                "connection refused or lost during the handshake".into()
            }))),
            None => Err(unreachable(format!("no handshake within {limit:?}"))),
        }
    }

    /// Waits until the connection state satisfies `done`, at most `timeout`; returns that
    /// state, or `None` if it did not come. Woken by every change, never polling.
    pub fn wait_for_state(
        &self,
        timeout: Duration,
        mut done: impl FnMut(&ConnectionState) -> bool,
    ) -> Option<ConnectionState> {
        self.wait_until(Instant::now() + timeout, &mut done)
    }

    /// [`Client::wait_for_state`] with a deadline, for waiting on several clients at once.
    pub fn wait_until(
        &self,
        deadline: Instant,
        mut done: impl FnMut(&ConnectionState) -> bool,
    ) -> Option<ConnectionState> {
        self.board
            .wait_until(deadline, |s| done(&s.state).then(|| s.state.clone()))
    }

    pub fn host(&self) -> &str {
        &self.host
    }

    pub fn port(&self) -> u16 {
        self.port
    }

    pub fn state(&self) -> ConnectionState {
        self.board.read(|s| s.state.clone())
    }

    pub fn banner(&self) -> Option<Banner> {
        self.board.read(|s| s.banner.clone())
    }

    /// The devices the server reported, with driver names (from the last handshake).
    pub fn devices(&self) -> Vec<DeviceInfo> {
        self.board.read(|s| s.devices.clone())
    }

    /// Why the last connection ended (the server closed it, stalled, sent garbage …), if one
    /// has ended.
    pub fn last_disconnect(&self) -> Option<String> {
        self.board.read(|s| s.last_disconnect.clone())
    }

    /// The data mode in force (or to be restored on the next connection).
    pub fn data_mode(&self) -> DataMode {
        self.board.read(|s| s.data_mode)
    }

    /// The replace rules in force, in the order the server tries them.
    pub fn replace_rules(&self) -> Vec<ReplaceRule> {
        self.board.read(|s| s.replace_rules.clone())
    }

    /// Messages from the server that could not be used (undecodable, replies to nothing).
    pub fn rejected(&self) -> u64 {
        self.board.read(|s| s.rejected)
    }

    /// A device address on this server (host and port as libplayerc sends them).
    pub fn addr(&self, interf: Interface, index: u16) -> DevAddr {
        DevAddr {
            host: 0,
            robot: u32::from(self.port),
            interf,
            index,
        }
    }

    /// The newest DATA message of `subtype` from a subscribed device.
    pub fn latest(&self, addr: DevAddr, subtype: u8) -> Option<Stamped> {
        self.store.latest(addr.interf, addr.index, subtype)
    }

    /// The newest DATA message of every subscribed device and subtype, for whoever passes all
    /// of it on (a relay) without knowing which subtypes a device sends.
    pub fn newest_data(&self) -> Vec<Stamped> {
        self.store.all_latest()
    }

    /// Messages and bytes received from a device so far.
    pub fn stats(&self, addr: DevAddr) -> DeviceStats {
        self.store.stats(addr.interf, addr.index)
    }

    /// Closes the connection and ends its thread or task, waiting for it — except on a
    /// shared I/O thread, where the task may need that very thread to end.
    pub fn close(&mut self) {
        let _ = self.commands.send(Command::Shutdown);
        match self.runner.take() {
            Some(Runner::Thread(thread)) => {
                let _ = thread.join();
            }
            Some(Runner::Task(done)) if !SharedIo::on_its_threads() => {
                let done = done.into_inner().unwrap_or_else(|e| e.into_inner());
                let _ = done.recv();
            }
            Some(Runner::Task(_)) | None => {}
        }
    }
}

impl Drop for Client {
    fn drop(&mut self) {
        self.close();
    }
}

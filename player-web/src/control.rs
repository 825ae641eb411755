//! The controller's commands from a page: checked against the relay's rule (the same
//! [`CommandGate`] its Player ports use), then sent to the robot over the relay's upstream
//! connection. A base a page drove is stopped when the page stops repeating its velocity
//! (a held key released unseen, a frozen tab) and when the page goes away.

use std::collections::{BTreeMap, HashMap};
use std::net::IpAddr;
use std::sync::{Arc, RwLock};
use std::time::{Duration, Instant};

use player_proto::RobotId;
use player_proto::client::Client;
use player_proto::interfaces::planner::{Planner, PlannerCmd};
use player_proto::interfaces::position2d::{Position2d, Position2dCmdPos, Position2dCmdVel};
use player_proto::message::{Body, Message};
use player_proto::server::{CommandGate, Commanders, Peer};
use player_proto::wire::{DevAddr, Interface, MsgType};

use crate::page::FromPage;
use crate::refused::Refused;

/// How long a velocity holds without a repeat. The page repeats every 100 ms while a key is
/// held: five repeats lost in a row stop the base.
pub const DEAD_MAN: Duration = Duration::from_millis(500);

/// The robots a page may command, by name (as [`RobotId`] says it), and the rule for who may.
pub struct Control {
    gate: CommandGate,
    rule: Commanders,
    robots: RwLock<HashMap<String, Arc<Client>>>,
}

/// What one page has driven: the bases moving at its say, and when it last said so.
#[derive(Default)]
pub struct Driven {
    moving: BTreeMap<(String, DevAddr), Instant>,
}

impl Control {
    pub fn new(rule: Commanders) -> Control {
        Control {
            gate: CommandGate::new(rule),
            rule,
            robots: RwLock::new(HashMap::new()),
        }
    }

    /// Makes the robot `id` commandable from the pages (the relay's upstream client for it).
    pub fn add_robot(&self, id: RobotId, client: Arc<Client>) {
        let name = id.to_string();
        let mut robots = self.robots.write().unwrap_or_else(|e| e.into_inner());
        robots.insert(name, client);
    }

    /// Whether `peer` would be let command now (the page's badge), and the rule in words.
    pub fn standing(&self, peer: Peer) -> (bool, String) {
        let may = match self.rule {
            Commanders::Everyone => true,
            Commanders::Nobody => false,
            Commanders::Address(ip) => peer.ip == ip,
            // Control goes to whoever commands first; say who could.
            Commanders::FirstToAsk => true,
        };
        let rule = match self.rule {
            Commanders::Everyone => "everyone may command".to_string(),
            Commanders::Nobody => "read-only: nobody may command".to_string(),
            Commanders::Address(ip) => format!("only {ip} may command"),
            Commanders::FirstToAsk => "the first page to command controls".to_string(),
        };
        (may, rule)
    }

    /// Carries out a page's command, or says why not.
    pub fn execute(
        &self,
        peer: Peer,
        command: FromPage,
        driven: &mut Driven,
    ) -> Result<(), Refused> {
        let (robot, device) = match &command {
            FromPage::Goal { robot, device, .. } | FromPage::Velocity { robot, device, .. } => {
                (robot.clone(), *device)
            }
            // What a page has in view is the hub's, not a command (see `socket`).
            FromPage::Show { .. } => return Ok(()),
        };
        if device.interf != Interface::POSITION2D {
            return Err(Refused::NotABase(device));
        }
        let client = self
            .robots
            .read()
            .unwrap_or_else(|e| e.into_inner())
            .get(&robot)
            .cloned()
            .ok_or_else(|| Refused::NoRobot(robot.clone()))?;
        let devices = client.devices();
        let has = |interf: Interface| {
            devices
                .iter()
                .any(|d| (d.addr.interf, d.addr.index) == (interf, device.index))
        };
        if !has(device.interf) {
            return Err(Refused::NoDevice { robot, device });
        }
        let (addr, body) = match command {
            FromPage::Velocity { command, .. } => {
                let moving = command.vel != Default::default();
                let key = (robot.clone(), device);
                if moving {
                    driven.moving.insert(key, Instant::now());
                } else {
                    driven.moving.remove(&key);
                }
                (device, Body::Position2d(Position2d::Velocity(command)))
            }
            FromPage::Show { .. } => return Ok(()),
            FromPage::Goal { goal, .. } => {
                if has(Interface::PLANNER) {
                    let addr = DevAddr::local(Interface::PLANNER, device.index);
                    (addr, Body::Planner(Planner::Goal(PlannerCmd { goal })))
                } else {
                    let command = Position2dCmdPos {
                        pos: goal,
                        state: 1,
                        ..Position2dCmdPos::default()
                    };
                    (device, Body::Position2d(Position2d::Position(command)))
                }
            }
        };
        let message = Message::typed(addr, MsgType::Cmd, body.clone());
        if !self.gate.admits(peer, &message) {
            let rule = self.standing(peer).1;
            return Err(Refused::Observer { rule });
        }
        client
            .try_command(client.addr(addr.interf, addr.index), body)
            .map_err(|source| Refused::NotSent {
                robot,
                device: addr,
                source,
            })
    }

    /// Stops every base `driven` moves whose velocity was not repeated within [`DEAD_MAN`]
    /// (all of them with `all`, when the page goes); returns how many.
    pub fn stop_stale(&self, peer: Peer, driven: &mut Driven, all: bool) -> usize {
        let now = Instant::now();
        let stale: Vec<(String, DevAddr)> = driven
            .moving
            .iter()
            .filter(|(_, at)| all || now.duration_since(**at) > DEAD_MAN)
            .map(|(key, _)| key.clone())
            .collect();
        for (robot, device) in &stale {
            driven.moving.remove(&(robot.clone(), *device));
            let stop = FromPage::Velocity {
                robot: robot.clone(),
                device: *device,
                command: Position2dCmdVel::default(),
            };
            if let Err(e) = self.execute(peer, stop, &mut Driven::default()) {
                tracing::warn!("{robot} {device}: not stopped: {e}");
            }
        }
        stale.len()
    }

    /// A page went: control it held is free again.
    pub fn left(&self, peer: Peer) {
        self.gate.left(peer);
    }
}

/// A page's identity for the gate.
pub fn peer(id: u64, ip: IpAddr) -> Peer {
    Peer { id, ip }
}

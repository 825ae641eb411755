//! Which devices each robot exposes on which port: read from the Player .cfg files that run the
//! world (`driver ( name "stage" provides [ "6665:position2d:0" … ] model "r0" )`,
//! `rangertolaser` for a laser, `mapfile` for a map, `passthrough` to reach another server's
//! devices), or, without one, one port per robot in world order.

mod beside;
mod defaults;
mod drivers;
mod navigation;
mod speech;
mod stage;

use std::path::Path;

use player_proto::wire::{DevAddr, Interface};

pub use beside::{cfgs_beside, devices_beside};
pub use defaults::{default_devices, shift_ports};
pub use navigation::attach_navigation;

use crate::mapfile::SharedMap;
use crate::nav::{LocalizeSettings, NavDriver, PlannerSpec};
use crate::world::World;
use crate::worldfile::{Block, Item, Value, WorldFileError, parse_text};

/// Where a served device's data comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Source {
    Simulation,
    Position {
        robot: usize,
    },
    Ranger {
        robot: usize,
        ranger: usize,
    },
    /// A one-sensor ranger seen through Player's `rangertolaser`.
    Laser {
        robot: usize,
        ranger: usize,
    },
    /// A sonar ring seen as a `sonar` device.
    Sonar {
        robot: usize,
        ranger: usize,
    },
    Fiducial {
        robot: usize,
        finder: usize,
    },
    /// A camera: raw RGB888 frames, or JPEG at this quality (1–100) when served through
    /// Player's `cameracompress`.
    Camera {
        robot: usize,
        camera: usize,
        jpeg_quality: Option<u8>,
    },
    Blobfinder {
        robot: usize,
        finder: usize,
    },
    Gripper {
        robot: usize,
        gripper: usize,
    },
    /// A robot's power pack (the world file's `joules`).
    Power {
        robot: usize,
    },
    /// A map image read by Player's `mapfile` driver.
    Map(SharedMap),
    /// The hypotheses of a localization driver (`amcl`, `fakelocalize`).
    Localize(NavDriver<LocalizeSettings>),
    /// A localization driver's estimate served as a `position2d` (amcl's second device).
    Estimate(NavDriver<LocalizeSettings>),
    /// A `wavefront` planner.
    Planner(NavDriver<PlannerSpec>),
    /// Sentences "heard" from a file or standard input (driver `sentences`).
    SpeechRecognition(crate::speech::SpeechInput),
    /// Text to say, logged and spoken (driver `festival`).
    Speech(crate::speech::SpeechOutput),
}

impl Source {
    /// Player's navigation drivers stamp their hypotheses and planner state with the server's
    /// clock (the wall clock), not the simulation's as Stage's devices do.
    pub fn stamped_by_wall_clock(&self) -> bool {
        matches!(self, Source::Localize(_) | Source::Planner(_))
    }
}

/// A device to serve.
#[derive(Debug, Clone, PartialEq)]
pub struct ServedDevice {
    pub port: u16,
    pub interf: Interface,
    pub index: u16,
    /// What DRIVERINFO reports.
    pub driver: String,
    pub source: Source,
}

impl ServedDevice {
    pub fn addr(&self) -> DevAddr {
        DevAddr {
            host: 0,
            robot: u32::from(self.port),
            interf: self.interf,
            index: self.index,
        }
    }
}

/// The port of addresses that name none, as `player` serves them without `-p`.
pub const DEFAULT_PORT: u16 = 6665;

/// A device address as a .cfg writes it: `interface:index`, `port:interface:index`,
/// `host:port:interface:index`, or with a key in front (`key:host:port:interface:index`,
/// host and port often empty: `"odometry:::position2d:0"`). The host is not kept: every
/// device player-sim serves is its own.
fn parse_addr(text: &str) -> Option<(u16, Interface, u16)> {
    // Player reads "7001:ranger:1 " (a space inside the quotes, as in Stage's autolab.cfg).
    let parts: Vec<&str> = text.trim().split(':').collect();
    let (port, interface, index) = match parts.as_slice() {
        [interface, index] => ("", *interface, *index),
        [port, interface, index] | [_, port, interface, index] | [_, _, port, interface, index] => {
            (*port, *interface, *index)
        }
        _ => return None,
    };
    let addr: DevAddr = format!("{interface}:{index}").parse().ok()?;
    let port = if port.is_empty() {
        DEFAULT_PORT
    } else {
        port.parse().ok()?
    };
    Some((port, addr.interf, addr.index))
}

/// The key of a keyed address (`"odometry:::position2d:0"` → `odometry`).
fn addr_key(text: &str) -> Option<&str> {
    let parts: Vec<&str> = text.trim().split(':').collect();
    (parts.len() == 5).then_some(parts[0])
}

fn strings(value: Option<&Value>) -> Vec<String> {
    match value {
        Some(Value::List(items)) => items
            .iter()
            .filter_map(|v| v.as_str().map(str::to_string))
            .collect(),
        Some(v) => v.as_str().map(|s| vec![s.to_string()]).unwrap_or_default(),
        None => Vec::new(),
    }
}

/// Reads a .cfg against its world. Drivers the simulator does not provide are reported in
/// `ignored`.
pub fn from_cfg(
    path: &Path,
    world: &World,
    ignored: &mut Vec<String>,
) -> Result<Vec<ServedDevice>, WorldFileError> {
    from_cfgs(&[path], world, ignored)
}

/// Reads several .cfg files as one set of servers, in order: a later file's `passthrough`
/// reaches the devices an earlier one provides, as a second `player` process reaches the first
/// (Stage's half, then the navigation half).
pub fn from_cfgs(
    paths: &[&Path],
    world: &World,
    ignored: &mut Vec<String>,
) -> Result<Vec<ServedDevice>, WorldFileError> {
    let mut served = Vec::new();
    let mut next_id = 0;
    for path in paths {
        read_cfg(path, world, &mut served, ignored, &mut next_id)?;
    }
    Ok(served)
}

/// A driver block being read: what it is called, provides and requires.
pub(crate) struct DriverBlock<'a> {
    pub block: &'a Block,
    pub name: String,
    pub requires: Vec<String>,
    /// The .cfg's folder: Player reads file names relative to it.
    pub folder: &'a Path,
    /// Tells this block apart from every other block of the .cfg files read together.
    pub id: usize,
}

impl DriverBlock<'_> {
    /// An error at the driver block.
    pub fn error(&self, message: impl Into<String>) -> WorldFileError {
        let pos = &self.block.pos;
        WorldFileError::at(&pos.file, pos.line, pos.col, message)
    }

    /// "ignored: <what> at file:line" for this block.
    pub fn ignored(&self, what: &str) -> String {
        let pos = &self.block.pos;
        format!("ignored: {what} at {}:{}", pos.file, pos.line)
    }

    /// The device the first `requires` entry names, among those provided so far.
    pub fn required<'s>(&self, served: &'s [ServedDevice]) -> Option<&'s ServedDevice> {
        let required = self.requires.first().and_then(|r| parse_addr(r))?;
        served
            .iter()
            .find(|d| (d.port, d.interf, d.index) == required)
    }

    /// The `requires` entry of interface `interf` with key `key` (any key when `None`), as
    /// Player's drivers look them up: the text, and the device it names if one is provided.
    pub fn required_as<'s>(
        &self,
        served: &'s [ServedDevice],
        interf: Interface,
        key: Option<&str>,
    ) -> Option<(&str, Option<&'s ServedDevice>)> {
        self.requires.iter().find_map(|text| {
            let (port, i, index) = parse_addr(text)?;
            if i != interf || key.is_some_and(|k| addr_key(text) != Some(k)) {
                return None;
            }
            let device = served
                .iter()
                .find(|d| (d.port, d.interf, d.index) == (port, i, index));
            Some((text.as_str(), device))
        })
    }
}

fn read_cfg(
    path: &Path,
    world: &World,
    served: &mut Vec<ServedDevice>,
    ignored: &mut Vec<String>,
    next_id: &mut usize,
) -> Result<(), WorldFileError> {
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| WorldFileError::at(&name, 1, 1, format!("cannot read: {e}")))?;
    let folder = path.parent().unwrap_or(Path::new("."));
    for item in parse_text(&text, &name)? {
        let Item::Block(block) = item else { continue };
        if block.kind != "driver" {
            ignored.push(format!(
                "ignored: {} at {}:{}",
                block.kind, block.pos.file, block.pos.line
            ));
            continue;
        }
        let driver = DriverBlock {
            block: &block,
            name: block
                .get("name")
                .and_then(|p| p.value.as_str())
                .unwrap_or("")
                .to_string(),
            requires: strings(block.get("requires").map(|p| &p.value)),
            folder,
            id: *next_id,
        };
        *next_id += 1;
        if let Some(note) = drivers::not_served(&driver) {
            if !ignored.contains(&note) {
                ignored.push(note);
            }
            continue;
        }
        let provides = strings(block.get("provides").map(|p| &p.value));
        let report_as = block
            .get("report_as")
            .and_then(|p| p.value.as_str())
            .map(str::to_string);
        let mut counts = stage::Counts::default();
        for text in &provides {
            let (port, interf, index) = parse_addr(text)
                .ok_or_else(|| driver.error(format!("bad device address {text:?}")))?;
            let source = match driver.name.as_str() {
                "stage" => stage::source(&driver, world, text, interf, &mut counts, ignored)?,
                "amcl" | "fakelocalize" | "wavefront" => {
                    navigation::source(&driver, world, served, interf, ignored)?
                }
                "sentences" | "festival" => speech::source(&driver, interf, ignored)?,
                _ => drivers::source(&driver, served, interf, ignored)?,
            };
            let Some(source) = source else { continue };
            served.push(ServedDevice {
                port,
                interf,
                index,
                driver: report_as.clone().unwrap_or_else(|| driver.name.clone()),
                source,
            });
        }
    }
    Ok(())
}

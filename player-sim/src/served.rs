//! Which devices each robot exposes on which port: read from the Player .cfg that runs the
//! world (`driver ( name "stage" provides [ "6665:position2d:0" … ] model "r0" )`,
//! `rangertolaser` for a laser), or, without one, one port per robot in world order.

use std::path::Path;

use player_proto::wire::{DevAddr, Interface};

use crate::world::World;
use crate::worldfile::{Item, Value, WorldFileError, parse_text};

/// Where a served device's data comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
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

const DEFAULT_PORT: u16 = 6665;

fn parse_addr(text: &str) -> Option<(u16, Interface, u16)> {
    // Player reads "7001:ranger:1 " (a space inside the quotes, as in Stage's autolab.cfg).
    let addr: DevAddr = text.trim().parse().ok()?;
    let port = if addr.robot == 0 {
        DEFAULT_PORT
    } else {
        u16::try_from(addr.robot).ok()?
    };
    Some((port, addr.interf, addr.index))
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
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| WorldFileError::at(&name, 1, 1, format!("cannot read: {e}")))?;
    let mut served: Vec<ServedDevice> = Vec::new();
    for item in parse_text(&text, &name)? {
        let Item::Block(block) = item else { continue };
        if block.kind != "driver" {
            ignored.push(format!(
                "ignored: {} at {}:{}",
                block.kind, block.pos.file, block.pos.line
            ));
            continue;
        }
        let driver = block
            .get("name")
            .and_then(|p| p.value.as_str())
            .unwrap_or("")
            .to_string();
        let provides = strings(block.get("provides").map(|p| &p.value));
        let requires = strings(block.get("requires").map(|p| &p.value));
        let report_as = block
            .get("report_as")
            .and_then(|p| p.value.as_str())
            .map(str::to_string);
        let at = |message: String| {
            WorldFileError::at(&block.pos.file, block.pos.line, block.pos.col, message)
        };
        let mut counts = [0usize; 3];
        for text in &provides {
            let (port, interf, index) =
                parse_addr(text).ok_or_else(|| at(format!("bad device address {text:?}")))?;
            let source = match (driver.as_str(), interf) {
                ("stage", Interface::SIMULATION) => Source::Simulation,
                ("stage", _) => {
                    let model = block
                        .get("model")
                        .and_then(|p| p.value.as_str())
                        .ok_or_else(|| {
                            at(format!("stage driver providing {text} needs a model"))
                        })?;
                    let robot = world
                        .robots
                        .iter()
                        .position(|r| r.name == model)
                        .ok_or_else(|| at(format!("no robot {model:?} in the world")))?;
                    let spec = &world.robots[robot];
                    let too_many = |model: &str, what: &str, has: usize| {
                        at(format!(
                            "{text}: {model} has only {has} {what}(s) in the world, \
                             so the .cfg provides one too many"
                        ))
                    };
                    match interf {
                        Interface::POSITION2D => Source::Position { robot },
                        Interface::RANGER => {
                            let ranger = next_index(&mut counts[0], spec.rangers.len())
                                .ok_or_else(|| too_many(model, "ranger", spec.rangers.len()))?;
                            Source::Ranger { robot, ranger }
                        }
                        Interface::FIDUCIAL => {
                            let finder = next_index(&mut counts[1], spec.fiducials.len())
                                .ok_or_else(|| {
                                    too_many(model, "fiducial finder", spec.fiducials.len())
                                })?;
                            Source::Fiducial { robot, finder }
                        }
                        Interface::CAMERA => {
                            let camera = next_index(&mut counts[2], spec.cameras.len())
                                .ok_or_else(|| too_many(model, "camera", spec.cameras.len()))?;
                            Source::Camera {
                                robot,
                                camera,
                                jpeg_quality: None,
                            }
                        }
                        other => {
                            ignored.push(format!(
                                "ignored: {other} of {model} (not simulated yet) at {}:{}",
                                block.pos.file, block.pos.line
                            ));
                            continue;
                        }
                    }
                }
                ("rangertolaser" | "rangertosonar", _) => {
                    let required =
                        requires
                            .first()
                            .and_then(|r| parse_addr(r))
                            .ok_or_else(|| {
                                at(format!("{driver} needs requires [ \"port:ranger:N\" ]"))
                            })?;
                    let from = served
                        .iter()
                        .find(|d| (d.port, d.interf, d.index) == required)
                        .ok_or_else(|| {
                            at(format!(
                                "{driver} requires a ranger no driver provides before it"
                            ))
                        })?;
                    let Source::Ranger { robot, ranger } = from.source else {
                        return Err(at(format!("{driver} must require a ranger")));
                    };
                    if driver == "rangertolaser" {
                        Source::Laser { robot, ranger }
                    } else {
                        Source::Sonar { robot, ranger }
                    }
                }
                ("cameracompress", Interface::CAMERA) => {
                    let from = required_device(&served, &requires).ok_or_else(|| {
                        at(format!(
                            "{driver} requires a camera no driver provides before it"
                        ))
                    })?;
                    let Source::Camera { robot, camera, .. } = from.source else {
                        return Err(at(format!("{driver} must require a camera")));
                    };
                    let quality = match block.get("image_quality") {
                        None => crate::camera_frames::DEFAULT_JPEG_QUALITY,
                        Some(p) => match p.value.as_f64() {
                            Some(q) if q > 0.0 && q <= 1.0 => (q * 100.0).round().max(1.0) as u8,
                            _ => {
                                return Err(WorldFileError::at(
                                    &p.pos.file,
                                    p.pos.line,
                                    p.pos.col,
                                    "image_quality must be a number in (0, 1]",
                                ));
                            }
                        },
                    };
                    Source::Camera {
                        robot,
                        camera,
                        jpeg_quality: Some(quality),
                    }
                }
                _ => {
                    ignored.push(format!(
                        "ignored: driver {driver:?} at {}:{}",
                        block.pos.file, block.pos.line
                    ));
                    continue;
                }
            };
            served.push(ServedDevice {
                port,
                interf,
                index,
                driver: report_as.clone().unwrap_or_else(|| driver.clone()),
                source,
            });
        }
    }
    Ok(served)
}

/// Hands out the next index of a kind of sensor, if the model has that many.
fn next_index(count: &mut usize, available: usize) -> Option<usize> {
    (*count < available).then(|| {
        *count += 1;
        *count - 1
    })
}

/// The device a converting driver's `requires [ "port:interface:index" ]` names, among those
/// provided so far.
fn required_device<'a>(
    served: &'a [ServedDevice],
    requires: &[String],
) -> Option<&'a ServedDevice> {
    let required = requires.first().and_then(|r| parse_addr(r))?;
    served
        .iter()
        .find(|d| (d.port, d.interf, d.index) == required)
}

/// Without a .cfg: robot i on `base + i` with all its devices; the simulation on `base`.
pub fn default_devices(world: &World, base: u16) -> Vec<ServedDevice> {
    let mut served = vec![ServedDevice {
        port: base,
        interf: Interface::SIMULATION,
        index: 0,
        driver: "stage".into(),
        source: Source::Simulation,
    }];
    for (robot, spec) in world.robots.iter().enumerate() {
        let port = base.saturating_add(u16::try_from(robot).unwrap_or(u16::MAX));
        let mut add = |interf, index: usize, driver: &str, source| {
            served.push(ServedDevice {
                port,
                interf,
                index: index as u16,
                driver: driver.into(),
                source,
            });
        };
        add(
            Interface::POSITION2D,
            0,
            "stage",
            Source::Position { robot },
        );
        let (mut lasers, mut sonars) = (0, 0);
        for (ranger, r) in spec.rangers.iter().enumerate() {
            add(
                Interface::RANGER,
                ranger,
                "stage",
                Source::Ranger { robot, ranger },
            );
            if r.is_laser_like() {
                add(
                    Interface::LASER,
                    lasers,
                    "rangertolaser",
                    Source::Laser { robot, ranger },
                );
                lasers += 1;
            } else {
                add(
                    Interface::SONAR,
                    sonars,
                    "rangertosonar",
                    Source::Sonar { robot, ranger },
                );
                sonars += 1;
            }
        }
        for finder in 0..spec.fiducials.len() {
            add(
                Interface::FIDUCIAL,
                finder,
                "stage",
                Source::Fiducial { robot, finder },
            );
        }
        for camera in 0..spec.cameras.len() {
            add(
                Interface::CAMERA,
                camera,
                "stage",
                Source::Camera {
                    robot,
                    camera,
                    jpeg_quality: None,
                },
            );
        }
    }
    served
}

/// Moves every port so that the lowest becomes `base`.
pub fn shift_ports(devices: &mut [ServedDevice], base: u16) {
    let Some(lowest) = devices.iter().map(|d| d.port).min() else {
        return;
    };
    for d in devices {
        d.port = base.saturating_add(d.port - lowest);
    }
}

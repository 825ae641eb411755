//! The teacher's spec: a TOML file naming the world, the robot the program drives, the limits
//! and the checks. Every value is read with its place, so that a mistake is reported as
//! `spec.toml:12:8: check "reaches the charger", radius: must be more than 0` before any
//! program runs.

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::time::Duration;

use player_sim::world::World;
use serde::Deserialize;
use toml::Spanned;

use crate::checks::{Check, Rule};
use crate::zone::Zone;

/// Why a spec cannot be used.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SpecError {
    #[error("cannot read the spec {path}: {source}")]
    Read {
        path: String,
        source: std::io::Error,
    },
    /// A mistake at a place in the spec.
    #[error("{path}:{line}:{column}: {field}: {message}")]
    At {
        path: String,
        line: usize,
        column: usize,
        /// The field, with the check it belongs to (`check "x", radius`).
        field: String,
        message: String,
    },
    #[error("{path}: the world {world}: {message}")]
    World {
        path: String,
        world: String,
        message: String,
    },
}

/// A spec ready to grade with.
#[derive(Debug, Clone)]
pub struct Spec {
    /// The spec file.
    pub path: PathBuf,
    /// The world file, resolved against the spec's folder.
    pub world: PathBuf,
    /// The robot the program drives.
    pub robot: String,
    /// Simulated seconds a run lasts at most.
    pub time_limit: f64,
    /// Wall-clock seconds a run lasts at most, whatever the program does.
    pub wall_limit: Duration,
    /// How long a step waits for the program's command.
    pub patience: Duration,
    pub seed: u64,
    pub lockstep: bool,
    pub checks: Vec<Check>,
}

impl Spec {
    /// Points of all checks.
    pub fn max_score(&self) -> f64 {
        self.checks.iter().map(|c| c.points).sum()
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSpec {
    world: Spanned<String>,
    robot: Spanned<String>,
    time_limit: Spanned<f64>,
    #[serde(default)]
    seed: u64,
    lockstep: Option<bool>,
    wall_limit: Option<Spanned<f64>>,
    patience: Option<Spanned<f64>>,
    #[serde(default, rename = "check")]
    checks: Vec<RawCheck>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCheck {
    name: Spanned<String>,
    kind: Spanned<String>,
    points: Spanned<f64>,
    x: Option<Spanned<f64>>,
    y: Option<Spanned<f64>>,
    radius: Option<Spanned<f64>>,
    xmin: Option<Spanned<f64>>,
    xmax: Option<Spanned<f64>>,
    ymin: Option<Spanned<f64>>,
    ymax: Option<Spanned<f64>>,
    within: Option<Spanned<f64>>,
    min: Option<Spanned<f64>>,
    speed: Option<Spanned<f64>>,
    target: Option<Spanned<String>>,
    distance: Option<Spanned<f64>>,
    share: Option<Spanned<f64>>,
    file: Option<Spanned<String>>,
    function: Option<Spanned<String>>,
}

/// The check kinds, as a teacher writes them.
pub const KINDS: &[&str] = &[
    "reach",
    "no_stall",
    "end_in_zone",
    "avoid_zone",
    "distance",
    "stop_at_end",
    "follow",
    "python",
];

/// Turns byte offsets of the spec's text into `line:column` errors.
struct Places<'a> {
    path: &'a Path,
    text: &'a str,
}

impl Places<'_> {
    fn error(&self, span: Range<usize>, field: &str, message: impl Into<String>) -> SpecError {
        let before = &self.text[..span.start.min(self.text.len())];
        let line = before.matches('\n').count() + 1;
        let column = before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
        SpecError::At {
            path: self.path.display().to_string(),
            line,
            column,
            field: field.to_string(),
            message: message.into(),
        }
    }

    /// A number that must be finite and above `low` (or at least, when `inclusive`).
    fn number(
        &self,
        v: &Spanned<f64>,
        field: &str,
        low: f64,
        inclusive: bool,
    ) -> Result<f64, SpecError> {
        let x = *v.get_ref();
        let fine = x.is_finite() && if inclusive { x >= low } else { x > low };
        if fine {
            Ok(x)
        } else {
            let bound = if inclusive { "at least" } else { "more than" };
            Err(self.error(v.span(), field, format!("must be {bound} {low}, got {x}")))
        }
    }
}

impl Spec {
    /// Reads and checks the spec at `path`, its world included.
    pub fn load(path: &Path) -> Result<Spec, SpecError> {
        let text = std::fs::read_to_string(path).map_err(|source| SpecError::Read {
            path: path.display().to_string(),
            source,
        })?;
        Spec::parse(path, &text)
    }

    /// Checks the spec `text`, read from `path` (its folder is where relative paths start).
    pub fn parse(path: &Path, text: &str) -> Result<Spec, SpecError> {
        let places = Places { path, text };
        let raw: RawSpec = toml::from_str(text).map_err(|e| {
            let span = e.span().unwrap_or(0..0);
            places.error(span, "spec", e.message().trim().to_string())
        })?;
        let folder = path.parent().unwrap_or(Path::new("."));
        let world_path = folder.join(raw.world.get_ref());
        if !world_path.is_file() {
            return Err(places.error(
                raw.world.span(),
                "world",
                format!("no world file at {}", world_path.display()),
            ));
        }
        let world = World::load(&world_path).map_err(|e| SpecError::World {
            path: path.display().to_string(),
            world: world_path.display().to_string(),
            message: e.to_string(),
        })?;
        let robot = raw.robot.get_ref().clone();
        let names: Vec<&str> = world.robots.iter().map(|r| r.name.as_str()).collect();
        if !names.contains(&robot.as_str()) {
            return Err(places.error(
                raw.robot.span(),
                "robot",
                format!(
                    "{} has no robot {robot:?} (it has {names:?})",
                    world_path.display()
                ),
            ));
        }
        let time_limit = places.number(&raw.time_limit, "time_limit", 0.0, false)?;
        let wall_limit = match &raw.wall_limit {
            Some(v) => places.number(v, "wall_limit", 0.0, false)?,
            None => 30.0 + 2.0 * time_limit,
        };
        let patience = match &raw.patience {
            Some(v) => places.number(v, "patience", 0.0, false)?,
            None => 5.0,
        };
        let mut checks = Vec::with_capacity(raw.checks.len());
        for check in &raw.checks {
            checks.push(check_of(&places, check, folder, &names)?);
        }
        Ok(Spec {
            path: path.to_path_buf(),
            world: world_path,
            robot,
            time_limit,
            wall_limit: Duration::from_secs_f64(wall_limit),
            patience: Duration::from_secs_f64(patience),
            seed: raw.seed,
            lockstep: raw.lockstep.unwrap_or(true),
            checks,
        })
    }
}

fn check_of(
    places: &Places<'_>,
    raw: &RawCheck,
    folder: &Path,
    robots: &[&str],
) -> Result<Check, SpecError> {
    let name = raw.name.get_ref().clone();
    let field = |f: &str| format!("check {name:?}, {f}");
    let need =
        |v: &Option<Spanned<f64>>, f: &str, low: f64, inclusive: bool| -> Result<f64, SpecError> {
            match v {
                Some(v) => places.number(v, &field(f), low, inclusive),
                None => Err(places.error(
                    raw.kind.span(),
                    &field(f),
                    format!("a {} check needs {f}", raw.kind.get_ref()),
                )),
            }
        };
    let any = |v: &Option<Spanned<f64>>, f: &str| need(v, f, f64::MIN, true);
    let zone = || -> Result<Zone, SpecError> {
        if raw.radius.is_some() {
            return Ok(Zone::Circle {
                x: any(&raw.x, "x")?,
                y: any(&raw.y, "y")?,
                radius: need(&raw.radius, "radius", 0.0, false)?,
            });
        }
        let (xmin, xmax) = (any(&raw.xmin, "xmin")?, any(&raw.xmax, "xmax")?);
        let (ymin, ymax) = (any(&raw.ymin, "ymin")?, any(&raw.ymax, "ymax")?);
        if xmin >= xmax || ymin >= ymax {
            return Err(places.error(
                raw.kind.span(),
                &field("xmin"),
                "a zone is x, y and radius, or xmin < xmax and ymin < ymax",
            ));
        }
        Ok(Zone::Box {
            xmin,
            xmax,
            ymin,
            ymax,
        })
    };
    let rule = match raw.kind.get_ref().as_str() {
        "reach" => Rule::Reach {
            zone: zone()?,
            within: match &raw.within {
                Some(v) => Some(places.number(v, &field("within"), 0.0, false)?),
                None => None,
            },
        },
        "no_stall" => Rule::NoStall,
        "end_in_zone" => Rule::EndIn(zone()?),
        "avoid_zone" => Rule::Avoid(zone()?),
        "distance" => Rule::Distance {
            min: need(&raw.min, "min", 0.0, false)?,
        },
        "stop_at_end" => Rule::StopAtEnd {
            speed: match &raw.speed {
                Some(v) => places.number(v, &field("speed"), 0.0, false)?,
                None => 0.05,
            },
        },
        "follow" => {
            let Some(target) = &raw.target else {
                return Err(places.error(
                    raw.kind.span(),
                    &field("target"),
                    "a follow check needs target, the robot to follow",
                ));
            };
            let Some(index) = robots.iter().position(|r| r == target.get_ref()) else {
                return Err(places.error(
                    target.span(),
                    &field("target"),
                    format!(
                        "the world has no robot {:?} (it has {robots:?})",
                        target.get_ref()
                    ),
                ));
            };
            let share = match &raw.share {
                Some(v) => places.number(v, &field("share"), 0.0, false)?,
                None => 0.8,
            };
            if share > 1.0 {
                let span = raw.share.as_ref().map_or(raw.kind.span(), Spanned::span);
                return Err(places.error(span, &field("share"), "a share of the run is at most 1"));
            }
            Rule::Follow {
                target: index,
                target_name: target.get_ref().clone(),
                distance: need(&raw.distance, "distance", 0.0, false)?,
                share,
            }
        }
        "python" => {
            let (Some(file), Some(function)) = (&raw.file, &raw.function) else {
                return Err(places.error(
                    raw.kind.span(),
                    &field("file"),
                    "a python check needs file (a .py beside the spec) and function",
                ));
            };
            let script = folder.join(file.get_ref());
            if !script.is_file() {
                return Err(places.error(
                    file.span(),
                    &field("file"),
                    format!("no Python file at {}", script.display()),
                ));
            }
            let valid_name = !function.get_ref().is_empty()
                && function
                    .get_ref()
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || c == '_');
            if !valid_name {
                return Err(places.error(
                    function.span(),
                    &field("function"),
                    "a Python function's name",
                ));
            }
            Rule::Python {
                file: script,
                function: function.get_ref().clone(),
            }
        }
        other => {
            return Err(places.error(
                raw.kind.span(),
                &field("kind"),
                format!("unknown check kind {other:?}; known: {}", KINDS.join(", ")),
            ));
        }
    };
    let points = places.number(&raw.points, &field("points"), 0.0, true)?;
    Ok(Check { name, points, rule })
}

//! Stage's built-in controllers a position model names with `ctrl "…"`: only `wander` is
//! simulated (Stage's example that cruises and turns away from what its ranger sees).

use super::models::Model;
use super::properties::err;
use super::{RangerSpec, World};
use crate::worldfile::{Value, WorldFileError};

/// Stage's wander controller uses the first ranger with more samples than this.
const WANDER_MIN_SAMPLES: usize = 8;

/// What drives a robot besides its clients.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Controller {
    /// Stage's `wander`, steering by the robot's ranger `ranger`.
    Wander { ranger: usize },
}

impl World {
    /// The controller `ctrl` names, once the robot's rangers are read; other controllers are
    /// reported as ignored. A wanderer without a ranger to see by is an error, as in Stage.
    pub(super) fn controller(
        &mut self,
        model: &Model,
        rangers: &[RangerSpec],
    ) -> Result<Option<Controller>, WorldFileError> {
        let Some(p) = model.get("ctrl") else {
            return Ok(None);
        };
        let names: Vec<&str> = match &p.value {
            Value::List(items) => items.iter().filter_map(Value::as_str).collect(),
            other => other.as_str().into_iter().collect(),
        };
        let mut found = None;
        for text in names {
            // "wander arg…": the first word names the controller, the rest are its arguments.
            let name = text.split_whitespace().next().unwrap_or("");
            if name != "wander" {
                self.ignore(
                    &format!("ctrl {text:?} (only \"wander\" is simulated)"),
                    &p.pos,
                );
                continue;
            }
            let ranger = rangers
                .iter()
                .position(|r| {
                    r.sensors
                        .first()
                        .is_some_and(|s| s.samples > WANDER_MIN_SAMPLES)
                })
                .ok_or_else(|| {
                    err(
                        &p.pos,
                        format!(
                            "ctrl \"wander\" needs a ranger with more than {WANDER_MIN_SAMPLES} \
                             samples on the robot"
                        ),
                    )
                })?;
            found = Some(Controller::Wander { ranger });
        }
        Ok(found)
    }
}

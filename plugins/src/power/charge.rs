//! What a power reading means to a person: how full, whether it is low, in words. Kept apart
//! from the drawing so that the rules are tested without a scene.

use player_proto::interfaces::power::{
    MASK_CHARGING, MASK_JOULES, MASK_PERCENT, MASK_VOLTS, MASK_WATTS, PowerData,
};

/// When a battery counts as low.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Thresholds {
    pub low_percent: f32,
    /// 0 turns the voltage rule off.
    pub low_volts: f32,
}

/// How worried a person should be.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Level {
    Fine,
    Low,
    /// Under half the low threshold: bring it home now.
    Empty,
}

/// One reading, with only the fields the device said are valid.
#[derive(Debug, Clone, PartialEq)]
pub struct Charge {
    pub percent: Option<f32>,
    pub volts: Option<f32>,
    pub joules: Option<f32>,
    pub watts: Option<f32>,
    pub charging: Option<bool>,
    pub level: Level,
    /// The threshold the level was judged by, for the warning's words.
    judged_by: Option<String>,
}

impl Charge {
    pub(super) fn read(data: &PowerData, limits: &Thresholds) -> Charge {
        let valid = |mask: u32| data.valid & mask != 0;
        let percent = valid(MASK_PERCENT).then_some(data.percent);
        let volts = valid(MASK_VOLTS).then_some(data.volts);
        let (level, judged_by) = match (percent, volts) {
            (Some(p), _) => (
                level_of(p, limits.low_percent),
                Some(format!("under {:.0} %", limits.low_percent)),
            ),
            (None, Some(v)) if limits.low_volts > 0.0 => (
                // Volts sag far less than charge: "empty" is the low mark minus a tenth.
                if v < limits.low_volts * 0.9 {
                    Level::Empty
                } else if v < limits.low_volts {
                    Level::Low
                } else {
                    Level::Fine
                },
                Some(format!("under {:.1} V", limits.low_volts)),
            ),
            _ => (Level::Fine, None),
        };
        Charge {
            percent,
            volts,
            joules: valid(MASK_JOULES).then_some(data.joules),
            watts: valid(MASK_WATTS).then_some(data.watts),
            charging: valid(MASK_CHARGING).then_some(data.charging > 0),
            level,
            judged_by,
        }
    }

    /// How full, 0..=1, when the device says.
    pub fn fraction(&self) -> Option<f32> {
        self.percent.map(|p| (p / 100.0).clamp(0.0, 1.0))
    }

    /// The gauge's label: the percentage, else the voltage.
    pub fn short_text(&self) -> String {
        match (self.percent, self.volts) {
            (Some(p), _) => format!("{p:.0} %"),
            (None, Some(v)) => format!("{v:.1} V"),
            (None, None) => "?".into(),
        }
    }

    /// The item tree's warning.
    pub fn warning(&self) -> String {
        let how = match self.level {
            Level::Fine => return String::new(),
            Level::Low => "battery low",
            Level::Empty => "battery nearly empty",
        };
        let rule = self.judged_by.as_deref().unwrap_or_default();
        format!("{how}: {} ({rule})", self.short_text())
    }

    /// Every figure the device sent, one line each.
    pub fn figures(&self) -> Vec<String> {
        let mut lines = Vec::new();
        if let Some(p) = self.percent {
            lines.push(format!("charge {p:.0} %"));
        }
        if let Some(v) = self.volts {
            lines.push(format!("{v:.2} V"));
        }
        if let Some(j) = self.joules {
            lines.push(format!("{:.1} kJ stored", j / 1000.0));
        }
        if let Some(w) = self.watts {
            lines.push(format!("{w:.1} W"));
        }
        if let Some(c) = self.charging {
            lines.push(if c { "charging" } else { "not charging" }.into());
        }
        lines
    }
}

fn level_of(percent: f32, low: f32) -> Level {
    if percent < low / 2.0 {
        Level::Empty
    } else if percent < low {
        Level::Low
    } else {
        Level::Fine
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const LIMITS: Thresholds = Thresholds {
        low_percent: 20.0,
        low_volts: 11.5,
    };

    fn reading(valid: u32, percent: f32, volts: f32) -> PowerData {
        PowerData {
            valid,
            percent,
            volts,
            ..PowerData::default()
        }
    }

    #[test]
    fn the_percentage_decides_when_there_is_one() {
        let both = MASK_PERCENT | MASK_VOLTS;
        assert_eq!(
            Charge::read(&reading(both, 55.0, 10.0), &LIMITS).level,
            Level::Fine
        );
        assert_eq!(
            Charge::read(&reading(both, 15.0, 13.0), &LIMITS).level,
            Level::Low
        );
        assert_eq!(
            Charge::read(&reading(both, 9.0, 13.0), &LIMITS).level,
            Level::Empty
        );
        let low = Charge::read(&reading(both, 15.0, 13.0), &LIMITS);
        assert_eq!(low.warning(), "battery low: 15 % (under 20 %)");
    }

    #[test]
    fn voltage_alone_is_judged_by_the_voltage_rule() {
        let volts = Charge::read(&reading(MASK_VOLTS, 0.0, 11.2), &LIMITS);
        assert_eq!((volts.level, volts.fraction()), (Level::Low, None));
        assert_eq!(volts.short_text(), "11.2 V");
        let off = Thresholds {
            low_volts: 0.0,
            ..LIMITS
        };
        assert_eq!(
            Charge::read(&reading(MASK_VOLTS, 0.0, 1.0), &off).level,
            Level::Fine
        );
    }

    #[test]
    fn fields_the_device_did_not_fill_are_not_shown() {
        let charge = Charge::read(&reading(MASK_PERCENT, 80.0, 99.0), &LIMITS);
        assert_eq!(charge.volts, None);
        assert_eq!(charge.figures(), vec!["charge 80 %".to_string()]);
    }
}

//! Where a person wants the camera to look, in the degrees the sliders show, and the PTZ
//! command that asks for it (Player speaks radians). Kept apart from the window so the
//! conversion and its limits are tested alone.

use player_proto::interfaces::ptz::{PtzCmd, PtzData};

/// How far the sliders go, degrees: pan ±, tilt ±, zoom (field of view) up to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    pub pan: f32,
    pub tilt: f32,
    pub zoom: f32,
}

/// The aim being set, degrees.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aim {
    pub pan: f32,
    pub tilt: f32,
    pub zoom: f32,
}

impl Aim {
    /// The aim the device reports now.
    pub fn of(state: &PtzData) -> Aim {
        Aim {
            pan: state.pan.to_degrees(),
            tilt: state.tilt.to_degrees(),
            zoom: state.zoom.to_degrees(),
        }
    }

    /// The command for this aim within `limits`; speeds 0 leave them to the device.
    pub fn command(&self, limits: &Limits) -> PtzCmd {
        PtzCmd {
            pan: self.pan.clamp(-limits.pan, limits.pan).to_radians(),
            tilt: self.tilt.clamp(-limits.tilt, limits.tilt).to_radians(),
            zoom: self.zoom.clamp(0.0, limits.zoom).to_radians(),
            panspeed: 0.0,
            tiltspeed: 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const LIMITS: Limits = Limits {
        pan: 90.0,
        tilt: 30.0,
        zoom: 60.0,
    };

    #[test]
    fn degrees_become_radians_within_the_limits() {
        let aim = Aim {
            pan: 45.0,
            tilt: -50.0,
            zoom: 90.0,
        };
        let cmd = aim.command(&LIMITS);
        assert!((cmd.pan - std::f32::consts::FRAC_PI_4).abs() < 1e-6);
        assert!((cmd.tilt + 30f32.to_radians()).abs() < 1e-6, "clamped");
        assert!((cmd.zoom - 60f32.to_radians()).abs() < 1e-6, "clamped");
    }

    #[test]
    fn the_reported_state_reads_back_in_degrees() {
        let state = PtzData {
            pan: 0.5,
            tilt: -0.1,
            zoom: 1.0,
            ..PtzData::default()
        };
        let aim = Aim::of(&state);
        assert!((aim.pan - 28.6479).abs() < 1e-3);
        let back = aim.command(&Limits {
            pan: 180.0,
            tilt: 90.0,
            zoom: 180.0,
        });
        assert!((back.pan - 0.5).abs() < 1e-6 && (back.zoom - 1.0).abs() < 1e-6);
    }
}

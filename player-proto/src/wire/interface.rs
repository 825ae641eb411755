//! Interface codes: the number in every device address, and the name used in config strings
//! such as `laser:0`.

use std::fmt;

/// A Player interface code (`PLAYER_<NAME>_CODE`). Codes not in Player's table are still valid
/// values: plugin interfaces use codes from 128 upwards.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
#[cfg_attr(any(test, feature = "proptest"), derive(proptest_derive::Arbitrary))]
pub struct Interface(pub u16);

macro_rules! interface_codes {
    ($( $konst:ident = $code:literal, $name:literal; )*) => {
        impl Interface {
            $( pub const $konst: Interface = Interface($code); )*

            /// Every interface Player 3.1 defines, as (code, name).
            pub const KNOWN: &'static [(Interface, &'static str)] = &[ $( (Interface($code), $name), )* ];
        }
    };
}

interface_codes! {
    PLAYER = 1, "player";
    POWER = 2, "power";
    GRIPPER = 3, "gripper";
    POSITION2D = 4, "position2d";
    SONAR = 5, "sonar";
    LASER = 6, "laser";
    BLOBFINDER = 7, "blobfinder";
    PTZ = 8, "ptz";
    AUDIO = 9, "audio";
    FIDUCIAL = 10, "fiducial";
    SPEECH = 12, "speech";
    GPS = 13, "gps";
    BUMPER = 14, "bumper";
    DIO = 20, "dio";
    AIO = 21, "aio";
    IR = 22, "ir";
    WIFI = 23, "wifi";
    LOCALIZE = 25, "localize";
    POSITION3D = 30, "position3d";
    SIMULATION = 31, "simulation";
    BLINKENLIGHT = 33, "blinkenlight";
    CAMERA = 40, "camera";
    MAP = 42, "map";
    PLANNER = 44, "planner";
    LOG = 45, "log";
    JOYSTICK = 49, "joystick";
    SPEECH_RECOGNITION = 50, "speech_recognition";
    OPAQUE = 51, "opaque";
    POSITION1D = 52, "position1d";
    ACTARRAY = 53, "actarray";
    LIMB = 54, "limb";
    GRAPHICS2D = 55, "graphics2d";
    RFID = 56, "rfid";
    WSN = 57, "wsn";
    GRAPHICS3D = 58, "graphics3d";
    HEALTH = 59, "health";
    IMU = 60, "imu";
    POINTCLOUD3D = 61, "pointcloud3d";
    RANGER = 62, "ranger";
    VECTORMAP = 63, "vectormap";
    BLACKBOARD = 64, "blackboard";
    STEREO = 65, "stereo";
    COOPOBJECT = 66, "coopobject";
}

impl Interface {
    /// The config-file name (`"laser"`), if Player defines this code.
    pub fn name(self) -> Option<&'static str> {
        Self::KNOWN
            .iter()
            .find(|(code, _)| *code == self)
            .map(|(_, name)| *name)
    }

    /// Looks an interface up by its config-file name. A bare number is accepted too, for plugin
    /// interfaces that have no name.
    pub fn from_name(name: &str) -> Option<Interface> {
        Self::KNOWN
            .iter()
            .find(|(_, known)| known.eq_ignore_ascii_case(name))
            .map(|(code, _)| *code)
            .or_else(|| name.parse().ok().map(Interface))
    }
}

impl fmt::Display for Interface {
    /// The name, or the number for codes Player does not define.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.name() {
            Some(name) => f.write_str(name),
            None => write!(f, "{}", self.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_codes_agree() {
        assert_eq!(Interface::from_name("ranger"), Some(Interface::RANGER));
        assert_eq!(Interface::RANGER.0, 62);
        assert_eq!(Interface::LASER.to_string(), "laser");
        assert_eq!(Interface(128).to_string(), "128");
        assert_eq!(Interface::from_name("128"), Some(Interface(128)));
        assert_eq!(Interface::from_name("warpdrive"), None);
    }
}

//! Typed proxies: one device of one interface, with its requests and data typed.

use super::{Client, RequestError, Stamped};
use crate::body_kind::{BodyKind, DataBody};
use crate::interfaces::camera::{Camera, CameraData};
use crate::interfaces::common::Pose2d;
use crate::interfaces::fiducial::{Fiducial, FiducialData, FiducialGeometry};
use crate::interfaces::laser::{Laser, LaserConfig, LaserGeometry, LaserScan};
use crate::interfaces::position2d::{
    Position2d, Position2dCmdPos, Position2dCmdVel, Position2dData, Position2dGeometry,
    Position2dPower,
};
use crate::interfaces::ranger::{
    Ranger, RangerConfig, RangerGeometry, RangerIntensities, RangerRanges,
};
use crate::interfaces::sonar::{Sonar, SonarData, SonarGeometry};
use crate::wire::{DevAddr, Interface};

macro_rules! proxy {
    ($(#[$meta:meta])* $name:ident, $interface:ident, $method:ident) => {
        $(#[$meta])*
        pub struct $name<'a> {
            client: &'a Client,
            addr: DevAddr,
        }

        impl Client {
            #[doc = concat!("The `", stringify!($method), "` device with this index.")]
            pub fn $method(&self, index: u16) -> $name<'_> {
                $name { client: self, addr: self.addr(Interface::$interface, index) }
            }
        }

        impl $name<'_> {
            pub fn addr(&self) -> DevAddr {
                self.addr
            }

            /// Subscribes; returns the driver name.
            pub fn subscribe(&self) -> Result<String, RequestError> {
                self.client.subscribe(self.addr)
            }

            pub fn unsubscribe(&self) -> Result<(), RequestError> {
                self.client.unsubscribe(self.addr)
            }

            fn fetch<T: Clone>(&self, kind: BodyKind<T>) -> Result<T, RequestError> {
                self.client.fetch(self.addr, kind)
            }

            fn newest<T: DataBody>(&self) -> Option<(T, Stamped)> {
                self.client.latest_of::<T>(self.addr)
            }
        }
    };
}

proxy!(
    /// A `laser` device.
    LaserProxy, LASER, laser
);
proxy!(
    /// A `position2d` device (a mobile base).
    Position2dProxy, POSITION2D, position2d
);
proxy!(
    /// A `sonar` device.
    SonarProxy, SONAR, sonar
);
proxy!(
    /// A `ranger` device.
    RangerProxy, RANGER, ranger
);
proxy!(
    /// A `fiducial` finder.
    FiducialProxy, FIDUCIAL, fiducial
);
proxy!(
    /// A `camera`.
    CameraProxy, CAMERA, camera
);

impl LaserProxy<'_> {
    pub fn geometry(&self) -> Result<LaserGeometry, RequestError> {
        self.fetch(Laser::REQ_GET_GEOM)
    }

    pub fn config(&self) -> Result<LaserConfig, RequestError> {
        self.fetch(Laser::REQ_GET_CONFIG)
    }

    /// The newest scan and when it arrived.
    pub fn scan(&self) -> Option<(LaserScan, Stamped)> {
        self.newest()
    }
}

impl Position2dProxy<'_> {
    /// Drive at (vx m/s, vy m/s, va rad/s), motors on.
    pub fn set_velocity(&self, vx: f64, vy: f64, va: f64) {
        let cmd = Position2dCmdVel {
            vel: Pose2d::new(vx, vy, va),
            state: 1,
        };
        self.client.command(self.addr, Position2d::Velocity(cmd));
    }

    /// Go to a pose (position mode), at the driver's default speeds.
    pub fn go_to(&self, target: Pose2d) {
        let cmd = Position2dCmdPos {
            pos: target,
            vel: Pose2d::default(),
            state: 1,
        };
        self.client.command(self.addr, Position2d::Position(cmd));
    }

    pub fn set_motor_power(&self, on: bool) -> Result<(), RequestError> {
        let power = Position2dPower {
            state: u8::from(on),
        };
        self.client
            .request_with(self.addr, Position2d::REQ_MOTOR_POWER, power)
            .map(|_| ())
    }

    pub fn geometry(&self) -> Result<Position2dGeometry, RequestError> {
        self.fetch(Position2d::REQ_GET_GEOM)
    }

    /// The newest odometry.
    pub fn state(&self) -> Option<(Position2dData, Stamped)> {
        self.newest()
    }
}

impl SonarProxy<'_> {
    pub fn geometry(&self) -> Result<SonarGeometry, RequestError> {
        self.fetch(Sonar::REQ_GET_GEOM)
    }

    pub fn ranges(&self) -> Option<(SonarData, Stamped)> {
        self.newest()
    }
}

impl RangerProxy<'_> {
    pub fn geometry(&self) -> Result<RangerGeometry, RequestError> {
        self.fetch(Ranger::REQ_GET_GEOM)
    }

    pub fn config(&self) -> Result<RangerConfig, RequestError> {
        self.fetch(Ranger::REQ_GET_CONFIG)
    }

    pub fn ranges(&self) -> Option<(RangerRanges, Stamped)> {
        self.newest()
    }

    /// The newest intensities (`PLAYER_RANGER_DATA_INTNS`), which Stage sends after each
    /// RANGE message.
    pub fn intensities(&self) -> Option<(RangerIntensities, Stamped)> {
        self.newest()
    }
}

impl FiducialProxy<'_> {
    pub fn geometry(&self) -> Result<FiducialGeometry, RequestError> {
        self.fetch(Fiducial::REQ_GET_GEOM)
    }

    pub fn markers(&self) -> Option<(FiducialData, Stamped)> {
        self.newest()
    }
}

impl CameraProxy<'_> {
    /// Asks for one frame (GET_IMAGE), for cameras that do not stream.
    pub fn request_image(&self) -> Result<CameraData, RequestError> {
        self.fetch(Camera::REQ_GET_IMAGE)
    }

    /// The newest frame (pixels shared with the receive buffer, not copied).
    pub fn frame(&self) -> Option<(CameraData, Stamped)> {
        self.newest()
    }
}

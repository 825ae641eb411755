//! Typed proxies: one device of one interface, with its requests and data typed.

use super::{Client, RequestError, Stamped};
use crate::interfaces::camera::{Camera, CameraData};
use crate::interfaces::common::Pose2d;
use crate::interfaces::fiducial::{self, Fiducial, FiducialData, FiducialGeometry};
use crate::interfaces::laser::{self, Laser, LaserConfig, LaserGeometry, LaserScan};
use crate::interfaces::position2d::{
    self, Position2d, Position2dCmdPos, Position2dCmdVel, Position2dData, Position2dGeometry,
    Position2dPower,
};
use crate::interfaces::ranger::{
    self, Ranger, RangerConfig, RangerGeometry, RangerIntensities, RangerRanges,
};
use crate::interfaces::sonar::{self, Sonar, SonarData, SonarGeometry};
use crate::message::{Body, Message};
use crate::wire::{DevAddr, Interface};

/// A reply whose body is not the structure the request promises.
fn unexpected(reply: &Message) -> RequestError {
    RequestError::Nack(Box::new(reply.clone()))
}

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

            fn ask(&self, subtype: u8, body: Body) -> Result<Message, RequestError> {
                self.client.request(self.addr, subtype, body)
            }

            fn newest(&self, subtype: u8) -> Option<Stamped> {
                self.client.latest(self.addr, subtype)
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
        let reply = self.ask(laser::REQ_GET_GEOM, Body::Empty)?;
        match reply.body {
            Body::Laser(Laser::Geometry(g)) => Ok(g),
            _ => Err(unexpected(&reply)),
        }
    }

    pub fn config(&self) -> Result<LaserConfig, RequestError> {
        let reply = self.ask(laser::REQ_GET_CONFIG, Body::Empty)?;
        match reply.body {
            Body::Laser(Laser::Config(c)) => Ok(c),
            _ => Err(unexpected(&reply)),
        }
    }

    /// The newest scan and when it arrived.
    pub fn scan(&self) -> Option<(LaserScan, Stamped)> {
        let s = self.newest(1)?;
        match &s.message.body {
            Body::Laser(Laser::Scan(scan)) => Some((scan.clone(), s)),
            _ => None,
        }
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
        let body = Body::Position2d(Position2d::MotorPower(Position2dPower {
            state: u8::from(on),
        }));
        self.ask(2, body).map(|_| ())
    }

    pub fn geometry(&self) -> Result<Position2dGeometry, RequestError> {
        let reply = self.ask(position2d::REQ_GET_GEOM, Body::Empty)?;
        match reply.body {
            Body::Position2d(Position2d::Geometry(g)) => Ok(g),
            _ => Err(unexpected(&reply)),
        }
    }

    /// The newest odometry.
    pub fn state(&self) -> Option<(Position2dData, Stamped)> {
        let s = self.newest(1)?;
        match &s.message.body {
            Body::Position2d(Position2d::State(d)) => Some((*d, s)),
            _ => None,
        }
    }
}

impl SonarProxy<'_> {
    pub fn geometry(&self) -> Result<SonarGeometry, RequestError> {
        let reply = self.ask(sonar::REQ_GET_GEOM, Body::Empty)?;
        match reply.body {
            Body::Sonar(Sonar::Geometry(g)) => Ok(g),
            _ => Err(unexpected(&reply)),
        }
    }

    pub fn ranges(&self) -> Option<(SonarData, Stamped)> {
        let s = self.newest(1)?;
        match &s.message.body {
            Body::Sonar(Sonar::Ranges(d)) => Some((d.clone(), s)),
            _ => None,
        }
    }
}

impl RangerProxy<'_> {
    pub fn geometry(&self) -> Result<RangerGeometry, RequestError> {
        let reply = self.ask(ranger::REQ_GET_GEOM, Body::Empty)?;
        match reply.body {
            Body::Ranger(Ranger::Geometry(g)) => Ok(g),
            _ => Err(unexpected(&reply)),
        }
    }

    pub fn config(&self) -> Result<RangerConfig, RequestError> {
        let reply = self.ask(ranger::REQ_GET_CONFIG, Body::Empty)?;
        match reply.body {
            Body::Ranger(Ranger::Config(c)) => Ok(c),
            _ => Err(unexpected(&reply)),
        }
    }

    pub fn ranges(&self) -> Option<(RangerRanges, Stamped)> {
        let s = self.newest(1)?;
        match &s.message.body {
            Body::Ranger(Ranger::Ranges(d)) => Some((d.clone(), s)),
            _ => None,
        }
    }

    /// The newest intensities (`PLAYER_RANGER_DATA_INTNS`), which Stage sends after each
    /// RANGE message.
    pub fn intensities(&self) -> Option<(RangerIntensities, Stamped)> {
        let s = self.newest(3)?;
        match &s.message.body {
            Body::Ranger(Ranger::Intensities(d)) => Some((d.clone(), s)),
            _ => None,
        }
    }
}

impl FiducialProxy<'_> {
    pub fn geometry(&self) -> Result<FiducialGeometry, RequestError> {
        let reply = self.ask(fiducial::REQ_GET_GEOM, Body::Empty)?;
        match reply.body {
            Body::Fiducial(Fiducial::Geometry(g)) => Ok(g),
            _ => Err(unexpected(&reply)),
        }
    }

    pub fn markers(&self) -> Option<(FiducialData, Stamped)> {
        let s = self.newest(1)?;
        match &s.message.body {
            Body::Fiducial(Fiducial::Scan(d)) => Some((d.clone(), s)),
            _ => None,
        }
    }
}

impl CameraProxy<'_> {
    /// Asks for one frame (GET_IMAGE), for cameras that do not stream.
    pub fn request_image(&self) -> Result<CameraData, RequestError> {
        let reply = self.ask(crate::interfaces::camera::REQ_GET_IMAGE, Body::Empty)?;
        match reply.body {
            Body::Camera(Camera::Image(d)) => Ok(d),
            _ => Err(unexpected(&reply)),
        }
    }

    /// The newest frame (pixels shared with the receive buffer, not copied).
    pub fn frame(&self) -> Option<(CameraData, Stamped)> {
        let s = self.newest(1)?;
        match &s.message.body {
            Body::Camera(Camera::State(d)) => Some((d.clone(), s)),
            _ => None,
        }
    }
}

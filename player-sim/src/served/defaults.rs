//! Serving without a .cfg: every device of every robot, one port per robot, and moving the
//! ports of a served set.

use player_proto::wire::Interface;

use super::{ServedDevice, Source};
use crate::world::World;

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
        for finder in 0..spec.blobfinders.len() {
            add(
                Interface::BLOBFINDER,
                finder,
                "stage",
                Source::Blobfinder { robot, finder },
            );
        }
        for gripper in 0..spec.grippers.len() {
            add(
                Interface::GRIPPER,
                gripper,
                "stage",
                Source::Gripper { robot, gripper },
            );
        }
        if spec.battery.is_some() {
            add(Interface::POWER, 0, "stage", Source::Power { robot });
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

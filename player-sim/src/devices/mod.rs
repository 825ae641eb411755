//! The simulated devices as a Player server presents them: requests answered from the world
//! (geometry, configuration, model poses), commands given to the robots, and each step's data.

mod blobfinder;
mod data;
mod gripper;
mod localize;
mod map;
mod planner;
mod power;
mod speech;

use std::sync::{Arc, Mutex};

use player_proto::body_kind::BodyKind;
use player_proto::interfaces::camera::Camera;
use player_proto::interfaces::common::{BBox2d, BBox3d, Pose2d, Pose3d};
use player_proto::interfaces::fiducial::{Fiducial, FiducialFov, FiducialGeometry};
use player_proto::interfaces::gripper::Gripper;
use player_proto::interfaces::laser::{Laser, LaserConfig, LaserGeometry};
use player_proto::interfaces::position2d::{self, Position2d, Position2dGeometry};
use player_proto::interfaces::ranger::{Ranger, RangerConfig, RangerGeometry};
use player_proto::interfaces::simulation::{Simulation as SimMsg, SimulationPose2d};
use player_proto::interfaces::sonar::{Sonar, SonarGeometry};
use player_proto::message::{Body, Message};
use player_proto::server::{Device, Reply};
use player_proto::wire::{DevAddr, MsgType};

use crate::camera_frames::camera_data;
use crate::served::{ServedDevice, Source};
use crate::sim::{Command, Simulation};
use crate::sim_record::PortRecord;
use crate::world::{Pose, RangerSpec, SensorSpec};

/// A served device, backed by the shared simulation.
pub struct SimDevice {
    pub sim: Arc<Mutex<Simulation>>,
    pub served: ServedDevice,
    /// The simulation's own recording of this device's port, and the device's address there.
    pub record: Option<(PortRecord, DevAddr)>,
    /// Send a new subscriber the data of the step the simulation is at (lockstep: it does not
    /// step until its clients command, and they read first).
    pub greets: bool,
}

fn pose3(p: Pose, z: f64) -> Pose3d {
    Pose3d {
        px: p.x,
        py: p.y,
        pz: z,
        pyaw: p.a,
        ..Pose3d::default()
    }
}

fn laser_sensor(ranger: &RangerSpec) -> &SensorSpec {
    &ranger.sensors[0]
}

/// Whether `request` is a request of `kind` (its interface, class and subtype).
fn asks<T>(request: &Message, kind: BodyKind<T>) -> bool {
    kind.kind().matches(&request.header)
}

/// A data message of `kind`, as [`SimDevice::data`] lists them.
fn data_of<T>(kind: BodyKind<T>, value: T) -> (u8, Body) {
    (kind.subtype(), kind.to_body(value))
}

/// A ranger's configuration, with the beam spacing the readings really have.
fn ranger_config(ranger: &RangerSpec) -> RangerConfig {
    let s = laser_sensor(ranger);
    let n = s.samples.max(1);
    RangerConfig {
        min_angle: -s.fov / 2.0,
        max_angle: s.fov / 2.0,
        angular_res: if n > 1 { s.fov / (n - 1) as f64 } else { s.fov },
        min_range: s.min_range,
        max_range: s.max_range,
        range_res: 0.01,
        frequency: 10.0,
    }
}

impl SimDevice {
    fn answer(&self, request: &Message) -> Reply {
        let mut sim = self.sim.lock().expect("simulation");
        match self.served.source.clone() {
            Source::Position { robot } => {
                let spec = &sim.world.robots[robot];
                if asks(request, Position2d::REQ_GET_GEOM) {
                    Reply::Ack(Body::Position2d(Position2d::Geometry(Position2dGeometry {
                        pose: Pose3d::default(),
                        size: BBox3d {
                            sl: spec.size[0],
                            sw: spec.size[1],
                            sh: spec.size[2],
                        },
                    })))
                } else if let Body::Position2d(Position2d::SetOdometry(set)) = &request.body {
                    let pose = Pose {
                        x: set.pose.px,
                        y: set.pose.py,
                        a: set.pose.pa,
                    };
                    sim.set_odometry(robot, pose);
                    Reply::Ack(Body::Empty)
                } else if request.header.msg_type == MsgType::Req
                    && request.header.subtype == position2d::REQ_RESET_ODOM
                {
                    sim.set_odometry(robot, Pose::default());
                    Reply::Ack(Body::Empty)
                } else if asks(request, Position2d::REQ_MOTOR_POWER)
                    || asks(request, Position2d::REQ_VELOCITY_MODE)
                    || asks(request, Position2d::REQ_POSITION_MODE)
                {
                    // Accepted, nothing to change.
                    Reply::Ack(Body::Empty)
                } else {
                    Reply::Nack
                }
            }
            Source::Ranger { robot, ranger } => {
                let spec = &sim.world.robots[robot].rangers[ranger];
                if asks(request, Ranger::REQ_GET_GEOM) {
                    Reply::Ack(Body::Ranger(Ranger::Geometry(RangerGeometry {
                        pose: pose3(spec.pose, 0.0),
                        size: BBox3d {
                            sw: 0.15,
                            sl: 0.15,
                            sh: 0.1,
                        },
                        element_poses: spec.sensors.iter().map(|s| pose3(s.pose, 0.0)).collect(),
                        element_sizes: spec.sensors.iter().map(|_| BBox3d::default()).collect(),
                    })))
                } else if asks(request, Ranger::REQ_GET_CONFIG) {
                    Reply::Ack(Body::Ranger(Ranger::Config(ranger_config(spec))))
                } else {
                    Reply::Nack
                }
            }
            Source::Laser { robot, ranger } => {
                let spec = &sim.world.robots[robot].rangers[ranger];
                let c = ranger_config(spec);
                if asks(request, Laser::REQ_GET_GEOM) {
                    Reply::Ack(Body::Laser(Laser::Geometry(LaserGeometry {
                        pose: pose3(spec.pose, 0.0),
                        size: BBox3d {
                            sw: 0.15,
                            sl: 0.15,
                            sh: 0.1,
                        },
                    })))
                } else if asks(request, Laser::REQ_GET_CONFIG) {
                    Reply::Ack(Body::Laser(Laser::Config(LaserConfig {
                        min_angle: c.min_angle as f32,
                        max_angle: c.max_angle as f32,
                        resolution: c.angular_res as f32,
                        max_range: c.max_range as f32,
                        range_res: c.range_res as f32,
                        intensity: 0,
                        scanning_frequency: c.frequency as f32,
                    })))
                } else {
                    Reply::Nack
                }
            }
            Source::Sonar { robot, ranger } => {
                let spec = &sim.world.robots[robot].rangers[ranger];
                if asks(request, Sonar::REQ_GET_GEOM) {
                    let on_robot = |s: &SensorSpec| crate::sim::on_robot(spec.pose, s.pose);
                    let poses = spec
                        .sensors
                        .iter()
                        .map(|s| pose3(on_robot(s), 0.0))
                        .collect();
                    Reply::Ack(Body::Sonar(Sonar::Geometry(SonarGeometry { poses })))
                } else {
                    Reply::Nack
                }
            }
            Source::Fiducial { robot, finder } => {
                let spec = &sim.world.robots[robot].fiducials[finder];
                if asks(request, Fiducial::REQ_GET_GEOM) {
                    Reply::Ack(Body::Fiducial(Fiducial::Geometry(FiducialGeometry {
                        pose: pose3(spec.pose, 0.0),
                        size: BBox3d {
                            sw: 0.05,
                            sl: 0.05,
                            sh: 0.05,
                        },
                        fiducial_size: BBox2d { sw: 0.4, sl: 0.4 },
                    })))
                } else if asks(request, Fiducial::REQ_GET_FOV) {
                    Reply::Ack(Body::Fiducial(Fiducial::Fov(FiducialFov {
                        min_range: spec.min_range as f32,
                        max_range: spec.max_range as f32,
                        view_angle: spec.fov as f32,
                    })))
                } else {
                    Reply::Nack
                }
            }
            Source::Camera {
                robot,
                camera,
                jpeg_quality,
            } => {
                if asks(request, Camera::REQ_GET_IMAGE) {
                    let frame = camera_data(&sim, robot, camera, jpeg_quality);
                    Reply::Ack(Body::Camera(Camera::Image(frame)))
                } else {
                    Reply::Nack
                }
            }
            Source::Map(map) => map::answer(&map.0, request),
            Source::Localize(driver) => localize::answer(&mut sim, &driver, request),
            Source::Estimate(_) => Reply::Nack,
            Source::Planner(driver) => planner::answer(&mut sim, &driver, request),
            Source::Blobfinder { .. }
            | Source::SpeechRecognition(_)
            | Source::Speech(_)
            | Source::Power { .. } => Reply::Nack,
            Source::Gripper { robot, gripper } => {
                if asks(request, Gripper::REQ_GET_GEOM) {
                    let geometry = gripper::geometry(&sim, robot, gripper);
                    Reply::Ack(Body::Gripper(Gripper::Geometry(geometry)))
                } else {
                    Reply::Nack
                }
            }
            Source::Simulation => match &request.body {
                Body::Simulation(SimMsg::Pose2d(asked)) => {
                    let name = asked.name.as_str();
                    let pose = match sim.robot_index(&name) {
                        Some(i) => Some(sim.robots[i].pose),
                        None => sim
                            .world
                            .obstacles
                            .iter()
                            .find(|o| o.name == name)
                            .map(|o| o.pose),
                    };
                    match pose {
                        Some(p) => Reply::Ack(Body::Simulation(SimMsg::Pose2d(SimulationPose2d {
                            name: asked.name.clone(),
                            pose: Pose2d::new(p.x, p.y, p.a),
                        }))),
                        None => Reply::Nack,
                    }
                }
                Body::Simulation(SimMsg::SetPose2d(set)) => {
                    let name = set.name.as_str();
                    let pose = Pose {
                        x: set.pose.px,
                        y: set.pose.py,
                        a: set.pose.pa,
                    };
                    if let Some(i) = sim.robot_index(&name) {
                        sim.robots[i].pose = pose;
                        Reply::Ack(Body::Empty)
                    } else if let Some(o) = sim.world.obstacles.iter_mut().find(|o| o.name == name)
                    {
                        o.pose = pose;
                        Reply::Ack(Body::Empty)
                    } else {
                        Reply::Nack
                    }
                }
                _ => Reply::Nack,
            },
        }
    }
}

impl Device for SimDevice {
    fn driver_name(&self) -> &str {
        &self.served.driver
    }

    fn greeting(&mut self) -> Vec<(u8, Body, f64)> {
        if !self.greets {
            return Vec::new();
        }
        let sim = self.sim.lock().expect("simulation");
        let id = u32::try_from(sim.steps).unwrap_or(u32::MAX);
        let time = sim.time;
        sim.sensing(|sim| {
            SimDevice::data(sim, &self.served.source, id)
                .into_iter()
                .map(|(subtype, body)| (subtype, body, time))
                .collect()
        })
    }

    fn on_subscribe(&mut self) -> bool {
        if let Source::Localize(driver) = &self.served.source {
            localize::subscribed(&mut self.sim.lock().expect("simulation"), driver);
        }
        true
    }

    fn on_command(&mut self, command: &Message) {
        if let Some((record, addr)) = &self.record {
            let time = self.sim.lock().expect("simulation").time;
            let mut recorded = command.clone().at(time);
            recorded.header.addr = *addr;
            record.raw(
                time,
                player_proto::capture::Direction::ClientToServer,
                &recorded,
            );
        }
        if let Source::Speech(output) = &self.served.source {
            speech::say(output, command);
            return;
        }
        if let Source::Planner(driver) = &self.served.source {
            planner::command(&mut self.sim.lock().expect("simulation"), driver, command);
            return;
        }
        if let Source::Gripper { robot, gripper } = self.served.source
            && let Some(told) = gripper::command(command)
        {
            let mut sim = self.sim.lock().expect("simulation");
            sim.robots[robot].grippers[gripper].command = told;
            return;
        }
        let Source::Position { robot } = self.served.source else {
            return;
        };
        let mut sim = self.sim.lock().expect("simulation");
        let command = match &command.body {
            Body::Position2d(Position2d::Velocity(v)) if v.state != 0 => Command::Velocity {
                vx: v.vel.px,
                vy: v.vel.py,
                va: v.vel.pa,
            },
            Body::Position2d(Position2d::Velocity(_)) => Command::Velocity {
                vx: 0.0,
                vy: 0.0,
                va: 0.0,
            },
            // Stage takes a car command's steering angle as the turn rate of a robot that is no
            // car (player-sim simulates every robot as diff or omni).
            Body::Position2d(Position2d::Car(c)) => Command::Velocity {
                vx: c.velocity,
                vy: 0.0,
                va: c.angle,
            },
            // Stage steers to the pose with its own speeds; the command's are not read.
            Body::Position2d(Position2d::Position(p)) => Command::GoTo {
                target: Pose {
                    x: p.pos.px,
                    y: p.pos.py,
                    a: p.pos.pa,
                },
            },
            _ => return,
        };
        sim.robots[robot].command = command;
    }

    fn on_request(&mut self, request: &Message) -> Reply {
        self.answer(request)
    }
}

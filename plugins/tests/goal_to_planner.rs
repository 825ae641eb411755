//! A selected robot and the planner that drives it, in one scene: a ground click on the robot
//! becomes the planner's goal (and the robot does not drive straight there); with the planner
//! reporting a robot elsewhere, the click drives the robot straight as before.

mod support;

use framework::PluginConfig;
use framework::config::DeviceRef;
use framework::device::RecordingDevice;
use framework::plugin::{Handled, InputEvent, Plugin, PluginContext};
use glam::Vec3;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::planner::{Planner, PlannerData};
use player_proto::interfaces::position2d::{Position2d, Position2dData};
use player_proto::message::{Body, Message};
use player_proto::{DevAddr, MsgType};
use support::{Harness, harness};

/// Where the robot's odometry puts it.
const ROBOT: (f64, f64) = (1.0, 1.0);
const CLICK: Vec3 = Vec3::new(3.0, 2.0, 0.0);

fn device(port: u16, addr: &str, driver: &str) -> Option<DeviceRef> {
    Some(DeviceRef {
        host: "localhost".into(),
        port,
        addr: addr.parse().unwrap(),
        driver: driver.into(),
    })
}

fn robot_config() -> PluginConfig {
    PluginConfig {
        library: "libpv3d_position2d".into(),
        id: "r0".into(),
        device: device(6666, "position2d:0", "stage"),
        ..PluginConfig::default()
    }
}

fn planner_config() -> PluginConfig {
    PluginConfig {
        library: "libpv3d_planner".into(),
        id: "wavefront".into(),
        device: device(6665, "planner:0", "wavefront"),
        ..PluginConfig::default()
    }
}

/// The planner's own device, beside the harness's (the robot's).
struct Scene2 {
    h: Harness,
    planner_device: RecordingDevice,
    robot: Box<dyn Plugin>,
    planner: Box<dyn Plugin>,
}

impl Scene2 {
    fn new(planner_reports: (f64, f64)) -> Scene2 {
        let mut h = harness();
        let robot = h.make(robot_config()).unwrap();
        let planner_device = RecordingDevice::default();
        let create = h.registry.constructor("libpv3d_planner").unwrap();
        let planner = {
            let now = h.now;
            let mut ctx = PluginContext::new(&mut h.scene, &mut h.anchors, now)
                .with_device(Some(&planner_device));
            create(planner_config(), &mut ctx).unwrap()
        };
        let state = Position2dData {
            pos: Pose2d::new(ROBOT.0, ROBOT.1, 0.0),
            ..Position2dData::default()
        };
        let position: DevAddr = "position2d:0".parse().unwrap();
        h.device.push(Message::typed(
            position,
            MsgType::Data,
            Position2d::State(state),
        ));
        let plan = PlannerData {
            pos: Pose2d::new(planner_reports.0, planner_reports.1, 0.5),
            ..PlannerData::default()
        };
        let planner_addr: DevAddr = "planner:0".parse().unwrap();
        planner_device.push(Message::typed(
            planner_addr,
            MsgType::Data,
            Planner::State(plan),
        ));
        let mut s = Scene2 {
            h,
            planner_device,
            robot,
            planner,
        };
        s.run_both();
        s
    }

    fn run_both(&mut self) {
        self.robot.run(&mut self.h.ctx());
        let Scene2 {
            h,
            planner_device,
            planner,
            ..
        } = self;
        let now = h.now;
        let mut ctx = PluginContext::new(&mut h.scene, &mut h.anchors, now)
            .with_device(Some(&*planner_device));
        planner.run(&mut ctx);
    }

    /// The robot selected, then a click on the ground.
    fn click(&mut self) -> Handled {
        self.robot
            .on_event(&InputEvent::Activated(true), &mut self.h.ctx());
        self.robot
            .on_event(&InputEvent::GroundClicked(CLICK), &mut self.h.ctx())
    }

    fn planner_goals(&self) -> Vec<Pose2d> {
        self.planner_device
            .commands
            .lock()
            .unwrap()
            .iter()
            .filter_map(|b| match b {
                Body::Planner(Planner::Goal(cmd)) => Some(cmd.goal),
                _ => None,
            })
            .collect()
    }

    fn robot_moving(&self) -> bool {
        self.h.device.commands.lock().unwrap().iter().any(|b| {
            matches!(b, Body::Position2d(Position2d::Velocity(v)) if v.vel.px != 0.0 || v.vel.pa != 0.0)
        })
    }
}

#[test]
fn a_click_on_a_robot_its_planner_drives_becomes_the_planners_goal() {
    let mut s = Scene2::new((ROBOT.0 + 0.1, ROBOT.1));
    assert_eq!(s.click(), Handled::Yes);
    s.run_both();
    s.run_both();
    let goals = s.planner_goals();
    assert_eq!(goals.len(), 1, "{goals:?}");
    let goal = goals[0];
    assert!((goal.px - 3.0).abs() < 1e-6 && (goal.py - 2.0).abs() < 1e-6);
    assert_eq!(goal.pa, 0.5, "the heading the planner reports is kept");
    assert!(!s.robot_moving(), "the robot does not drive straight");
}

#[test]
fn a_robot_no_planner_drives_still_drives_straight_to_the_click() {
    let mut s = Scene2::new((ROBOT.0 + 3.0, ROBOT.1 - 3.0));
    assert_eq!(s.click(), Handled::Yes);
    s.run_both();
    s.run_both();
    assert!(s.planner_goals().is_empty());
    assert!(s.robot_moving(), "driven straight, as without a planner");
}

//! Turning what the person asked for (joystick, target, "Follow") into Player commands, in the
//! plugin's drive mode: velocities steered by the viewer, or way-points the server drives to.
//! Safe by default: every way out (stop, arrival, link lost and back) ends in a zero velocity.

use std::time::Duration;

use glam::{Vec2, Vec3};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::position2d::{Position2d, Position2dCmdPos, Position2dCmdVel};
use player_proto::message::Body;

use super::Position2dPlugin;
use super::goal::{DriveMode, Goal, REACQUIRE, heading, stand_off};
use super::teleop::{joystick_velocity, steer_towards};
use framework::plugin::PluginContext;

/// How often velocity commands are repeated while driving.
const COMMAND_PERIOD: Duration = Duration::from_millis(100);
/// A way-point is sent again only once the wanted one moved this far, m.
const WAYPOINT_SLACK: f32 = 0.1;
/// In position mode the server drives; a point this close counts as reached, m.
const WAYPOINT_REACHED: f32 = 0.1;

impl Position2dPlugin {
    /// Sends a velocity (throttled while driving; a stop is always sent at once).
    pub(super) fn drive(&mut self, ctx: &PluginContext<'_>, speed: f32, turn: f32) {
        let Some(device) = ctx.device else { return };
        let stop = speed == 0.0 && turn == 0.0;
        if !stop
            && self
                .last_command
                .is_some_and(|t| ctx.now.saturating_duration_since(t) < COMMAND_PERIOD)
        {
            return;
        }
        let cmd = Position2dCmdVel {
            vel: Pose2d::new(f64::from(speed), 0.0, f64::from(turn)),
            state: 1,
        };
        device.command(Body::Position2d(Position2d::Velocity(cmd)));
        self.last_command = Some(ctx.now);
        self.moving = !stop;
        if stop {
            self.sent_waypoint = None;
        }
    }

    /// Sends a way-point (position mode), at the plugin's speed limits.
    fn send_waypoint(&mut self, ctx: &PluginContext<'_>, at: Vec2, yaw: f32) {
        let Some(device) = ctx.device else { return };
        let cmd = Position2dCmdPos {
            pos: Pose2d::new(f64::from(at.x), f64::from(at.y), f64::from(yaw)),
            vel: Pose2d::new(
                f64::from(self.limits.max_speed),
                0.0,
                f64::from(self.limits.max_turn),
            ),
            state: 1,
        };
        device.command(Body::Position2d(Position2d::Position(cmd)));
        self.last_command = Some(ctx.now);
        self.sent_waypoint = Some(at);
        self.moving = true;
    }

    /// Zero velocity, and forget the goal, the dragged target and the joystick.
    pub(super) fn stop(&mut self, ctx: &mut PluginContext<'_>) {
        let had_goal = self.goal.take().is_some();
        self.zone_guard.clear();
        self.joystick = None;
        self.dragging = None;
        if self.moving || had_goal || self.sent_waypoint.is_some() {
            self.drive(ctx, 0.0, 0.0);
        }
        self.redraw_trail(ctx.scene);
    }

    /// Starts working towards `goal` (replacing any other).
    pub(super) fn set_goal(&mut self, goal: Goal, ctx: &mut PluginContext<'_>) {
        self.goal = Some(goal);
        self.joystick = None;
        self.dragging = None;
        self.sent_waypoint = None;
        self.refused = None;
        self.zone_guard.clear();
        self.redraw_trail(ctx.scene);
        self.check_goal(ctx);
    }

    /// One step of tele-operation.
    pub(super) fn teleoperate(&mut self, ctx: &mut PluginContext<'_>) {
        if ctx.device.is_some_and(|d| d.read_only()) {
            // Observed only: nothing to drive, and nothing would be sent.
            return;
        }
        let connected = ctx.device.is_some_and(|d| d.is_connected());
        if !connected {
            // The connection dropped: forget what we were doing, so nothing resumes by itself.
            let was_driving = self.goal.is_some() || self.joystick.is_some();
            self.goal = None;
            self.joystick = None;
            self.moving = false;
            self.sent_waypoint = None;
            self.link_up = false;
            if was_driving {
                self.redraw_trail(ctx.scene);
            }
            return;
        }
        if !self.link_up {
            // Back (or up for the first time since it dropped): the server may still hold our
            // last command, so make sure the robot stands still.
            self.link_up = true;
            self.drive(ctx, 0.0, 0.0);
        }
        if let Some(deflection) = self.joystick {
            let (speed, turn) = joystick_velocity(deflection, self.limits);
            self.drive(ctx, speed, turn);
            if deflection == Vec2::ZERO {
                // The person let go: that zero was the last command.
                self.joystick = None;
            }
            return;
        }
        match self.goal.clone() {
            Some(Goal::Point(point)) => self.go_to_point(ctx, point),
            Some(Goal::Follow {
                mut target,
                last_seen,
            }) => {
                let robot = Vec2::new(self.pose.0, self.pose.1);
                let near = last_seen.extend(0.0);
                let mut seen = target
                    .locate(ctx.scene, near)
                    .map(|(_, at)| Vec3::truncate(at));
                if seen.is_none()
                    && let Some(next) = target.successor(ctx.scene, near, REACQUIRE)
                {
                    tracing::info!("{}: following {} now", self.config.id, next.name);
                    seen = Some(next.position.truncate());
                    target = next;
                }
                let object = seen.unwrap_or(last_seen);
                let moved = object.distance(last_seen) > 0.01;
                if moved {
                    self.goal = Some(Goal::Follow {
                        target,
                        last_seen: object,
                    });
                    self.redraw_trail(ctx.scene);
                }
                match stand_off(robot, object, self.follow_distance) {
                    Some(aim) => self.head_for(ctx, aim, heading(robot, object, self.pose.2)),
                    None if self.moving => self.drive(ctx, 0.0, 0.0),
                    None => {}
                }
            }
            None => {}
        }
    }

    fn go_to_point(&mut self, ctx: &mut PluginContext<'_>, point: Vec2) {
        let robot = Vec2::new(self.pose.0, self.pose.1);
        let arrived = match self.mode {
            DriveMode::Velocity => steer_towards(self.pose, point, self.limits).is_none(),
            DriveMode::Position => robot.distance(point) < WAYPOINT_REACHED,
        };
        if arrived {
            self.stop(ctx);
            return;
        }
        self.head_for(ctx, point, heading(robot, point, self.pose.2));
    }

    /// Drives towards `aim`, to face `yaw` there (position mode only); holds still while the
    /// way ahead enters a zone the robot avoids.
    fn head_for(&mut self, ctx: &mut PluginContext<'_>, aim: Vec2, yaw: f32) {
        let robot = Vec2::new(self.pose.0, self.pose.1);
        for query in self.zone_guard.look(ctx.now, robot, aim) {
            ctx.send(query);
        }
        if self.zone_guard.blocked_by().is_some() {
            if self.moving || self.sent_waypoint.is_some() {
                self.drive(ctx, 0.0, 0.0);
            }
            return;
        }
        match self.mode {
            DriveMode::Velocity => {
                if let Some((speed, turn)) = steer_towards(self.pose, aim, self.limits) {
                    self.drive(ctx, speed, turn);
                } else if self.moving {
                    self.drive(ctx, 0.0, 0.0);
                }
            }
            DriveMode::Position => {
                if self
                    .sent_waypoint
                    .is_none_or(|s| s.distance(aim) > WAYPOINT_SLACK)
                {
                    self.send_waypoint(ctx, aim, yaw);
                }
            }
        }
    }
}

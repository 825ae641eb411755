//! The `position2d` interface (code 4): a planar mobile base. Odometry, velocity and position
//! commands, geometry, motor power.

use super::common::{BBox3d, Pose2d, Pose3d};

/// Request subtypes whose request body is empty.
pub const REQ_GET_GEOM: u8 = 1;
pub const REQ_RESET_ODOM: u8 = 6;

xdr_struct! {
    /// `player_position2d_data_t`: odometric pose, velocity and stall flag.
    #[derive(Copy)]
    pub struct Position2dData {
        /// m, m, rad.
        pub pos: Pose2d,
        /// m/s, m/s, rad/s.
        pub vel: Pose2d,
        /// 1 = motors stalled (a collision, in a simulator).
        pub stall: u8,
    }
}

xdr_struct! {
    /// `player_position2d_cmd_vel_t`: drive at this velocity.
    #[derive(Copy)]
    pub struct Position2dCmdVel {
        pub vel: Pose2d,
        /// Motor enable: 1 = on.
        pub state: u8,
    }
}

xdr_struct! {
    /// `player_position2d_cmd_pos_t`: go to this pose (position mode).
    #[derive(Copy)]
    pub struct Position2dCmdPos {
        pub pos: Pose2d,
        /// Speeds to use while moving.
        pub vel: Pose2d,
        pub state: u8,
    }
}

xdr_struct! {
    /// `player_position2d_cmd_car_t`: forward speed and steering angle.
    #[derive(Copy)]
    pub struct Position2dCmdCar {
        pub velocity: f64,
        pub angle: f64,
    }
}

xdr_struct! {
    /// `player_position2d_cmd_vel_head_t`: forward speed and absolute heading.
    #[derive(Copy)]
    pub struct Position2dCmdVelHead {
        pub velocity: f64,
        pub angle: f64,
    }
}

xdr_struct! {
    /// `player_position2d_geom_t`: the base's pose on the robot and its size.
    #[derive(Copy)]
    pub struct Position2dGeometry {
        pub pose: Pose3d,
        pub size: BBox3d,
    }
}

xdr_struct! {
    /// `player_position2d_power_config_t`: 0 = off, 1 = on.
    #[derive(Copy)]
    pub struct Position2dPower {
        pub state: u8,
    }
}

xdr_struct! {
    /// `player_position2d_velocity_mode_config_t`: driver-specific mode number.
    #[derive(Copy)]
    pub struct Position2dVelocityMode {
        pub value: u32,
    }
}

xdr_struct! {
    /// `player_position2d_position_mode_req_t`: 0 = velocity control, 1 = position control.
    #[derive(Copy)]
    pub struct Position2dPositionMode {
        pub state: u32,
    }
}

xdr_struct! {
    /// `player_position2d_set_odom_req_t`.
    #[derive(Copy)]
    pub struct Position2dSetOdom {
        pub pose: Pose2d,
    }
}

xdr_struct! {
    /// `player_position2d_speed_pid_req_t` and `player_position2d_position_pid_req_t`.
    #[derive(Copy)]
    pub struct Position2dPid {
        pub kp: f32,
        pub ki: f32,
        pub kd: f32,
    }
}

xdr_struct! {
    /// `player_position2d_speed_prof_req_t`: max speed (m/s) and acceleration (m/s²).
    #[derive(Copy)]
    pub struct Position2dSpeedProfile {
        pub speed: f32,
        pub acc: f32,
    }
}

interface_messages! {
    /// Messages of the `position2d` interface. RESET_ODOM (request 6) has no body.
    pub enum Position2d for POSITION2D {
        Data 1 as DATA_STATE => State(Position2dData),
        Data 2 as DATA_GEOM => GeometryData(Position2dGeometry),
        Command 1 as CMD_VEL => Velocity(Position2dCmdVel),
        Command 2 as CMD_POS => Position(Position2dCmdPos),
        Command 3 as CMD_CAR => Car(Position2dCmdCar),
        Command 4 as CMD_VEL_HEAD => VelocityHeading(Position2dCmdVelHead),
        Request 1 as REQ_GET_GEOM => Geometry(Position2dGeometry),
        Request 2 as REQ_MOTOR_POWER => MotorPower(Position2dPower),
        Request 3 as REQ_VELOCITY_MODE => VelocityMode(Position2dVelocityMode),
        Request 4 as REQ_POSITION_MODE => PositionMode(Position2dPositionMode),
        Request 5 as REQ_SET_ODOM => SetOdometry(Position2dSetOdom),
        Request 7 as REQ_SPEED_PID => SpeedPid(Position2dPid),
        Request 8 as REQ_POSITION_PID => PositionPid(Position2dPid),
        Request 9 as REQ_SPEED_PROF => SpeedProfile(Position2dSpeedProfile),
    }
}

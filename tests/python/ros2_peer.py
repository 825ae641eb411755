"""A ROS 2 peer without ROS, for test_ros2_live.py: Eclipse Cyclone DDS (the DDS of
rmw_cyclonedds_cpp) with ROS 2's message types written from their .msg definitions, under
ROS 2's DDS names (topic /a/b is rt/a/b, type pkg/msg/T is pkg::msg::dds_::T_).

Run inside a network namespace of its own (loopback only, multicast on lo): it starts
player-sim and the bridge itself and prints what it saw as one line of JSON.

    unshare -n python ros2_peer.py drive PLAYER_SIM PLAYER_ROS2 simple.world
        reads r0's scans, odometry and fixed transforms, drives it with cmd_vel, lets the
        commands stop, sends a NaN and an absurd speed;
    unshare -n python ros2_peer.py nav PLAYER_SIM PLAYER_ROS2 navigation.world
        comes late for the map, sends a goal to the planner and a start to the localizer;

The relay's front is ros2_relay.py; faults (a teleop killed, a robot gone and back, a quiet
domain, ROS 2's graph) are ros2_faults.py.
"""

import json
import math
import socket
import subprocess
import sys
import time
from dataclasses import dataclass, field

from cyclonedds.core import Policy, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import array, float32, float64, int8, int32, sequence, uint32
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

import player3


@dataclass
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: int32 = 0
    nanosec: uint32 = 0


@dataclass
class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time = field(default_factory=Time)
    frame_id: str = ""


@dataclass
class LaserScan(IdlStruct, typename="sensor_msgs::msg::dds_::LaserScan_"):
    header: Header
    angle_min: float32
    angle_max: float32
    angle_increment: float32
    time_increment: float32
    scan_time: float32
    range_min: float32
    range_max: float32
    ranges: sequence[float32]
    intensities: sequence[float32]


@dataclass
class Vector3(IdlStruct, typename="geometry_msgs::msg::dds_::Vector3_"):
    x: float64 = 0.0
    y: float64 = 0.0
    z: float64 = 0.0


@dataclass
class Point(IdlStruct, typename="geometry_msgs::msg::dds_::Point_"):
    x: float64
    y: float64
    z: float64


@dataclass
class Quaternion(IdlStruct, typename="geometry_msgs::msg::dds_::Quaternion_"):
    x: float64
    y: float64
    z: float64
    w: float64


@dataclass
class Pose(IdlStruct, typename="geometry_msgs::msg::dds_::Pose_"):
    position: Point
    orientation: Quaternion


@dataclass
class PoseWithCovariance(IdlStruct, typename="geometry_msgs::msg::dds_::PoseWithCovariance_"):
    pose: Pose
    covariance: array[float64, 36]


@dataclass
class Twist(IdlStruct, typename="geometry_msgs::msg::dds_::Twist_"):
    linear: Vector3 = field(default_factory=Vector3)
    angular: Vector3 = field(default_factory=Vector3)


@dataclass
class TwistWithCovariance(IdlStruct, typename="geometry_msgs::msg::dds_::TwistWithCovariance_"):
    twist: Twist
    covariance: array[float64, 36]


@dataclass
class Odometry(IdlStruct, typename="nav_msgs::msg::dds_::Odometry_"):
    header: Header
    child_frame_id: str
    pose: PoseWithCovariance
    twist: TwistWithCovariance


@dataclass
class Transform(IdlStruct, typename="geometry_msgs::msg::dds_::Transform_"):
    translation: Vector3
    rotation: Quaternion


@dataclass
class TransformStamped(IdlStruct, typename="geometry_msgs::msg::dds_::TransformStamped_"):
    header: Header
    child_frame_id: str
    transform: Transform


@dataclass
class TFMessage(IdlStruct, typename="tf2_msgs::msg::dds_::TFMessage_"):
    transforms: sequence[TransformStamped]


@dataclass
class MapMetaData(IdlStruct, typename="nav_msgs::msg::dds_::MapMetaData_"):
    map_load_time: Time
    resolution: float32
    width: uint32
    height: uint32
    origin: Pose


@dataclass
class OccupancyGrid(IdlStruct, typename="nav_msgs::msg::dds_::OccupancyGrid_"):
    header: Header
    info: MapMetaData
    data: sequence[int8]


@dataclass
class PoseStamped(IdlStruct, typename="geometry_msgs::msg::dds_::PoseStamped_"):
    header: Header
    pose: Pose


@dataclass
class Path(IdlStruct, typename="nav_msgs::msg::dds_::Path_"):
    header: Header
    poses: sequence[PoseStamped]


@dataclass
class PoseWithCovarianceStamped(
    IdlStruct, typename="geometry_msgs::msg::dds_::PoseWithCovarianceStamped_"
):
    header: Header
    pose: PoseWithCovariance


def yaw_quaternion(yaw):
    return Quaternion(0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def loopback_with_multicast():
    for command in (
        ["ip", "link", "set", "lo", "up"],
        ["ip", "link", "set", "lo", "multicast", "on"],
        ["ip", "route", "add", "224.0.0.0/4", "dev", "lo"],
    ):
        subprocess.run(command, check=True)


def garbage_to_the_dds_ports():
    """Datagrams that are not RTPS, RTPS with lying sizes, and cut ones, to domain 0's
    discovery and user ports, unicast and multicast: the bridge must carry on."""
    noise = [
        b"",
        b"hello",
        b"RTPS\x02\x03\x01\x0f" + b"\xff" * 12 + b"\x15\x05\xff\xff" + b"\x00" * 8,
        b"RTPS\x02\x03" + b"\x00" * 2,
        bytes(range(256)) * 8,
    ]
    sender = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sent = 0
    for port in range(7400, 7420):
        for host in ("127.0.0.1", "239.255.0.1"):
            for datagram in noise:
                try:
                    sender.sendto(datagram, (host, port))
                    sent += 1
                except OSError:
                    pass
    sender.close()
    return sent


def wait_for(what, get, limit=30.0):
    deadline = time.monotonic() + limit
    while time.monotonic() < deadline:
        value = get()
        if value is not None:
            return value
        time.sleep(0.05)
    raise SystemExit(f"timed out waiting for {what}")


LATCHED = Qos(
    Policy.Reliability.Reliable(duration(seconds=1)),
    Policy.Durability.TransientLocal,
    Policy.History.KeepLast(1),
)
RELIABLE = Qos(Policy.Reliability.Reliable(duration(seconds=1)), Policy.History.KeepLast(10))


def main(mode, player_sim, bridge, world):
    loopback_with_multicast()
    port = free_port()
    sim = subprocess.Popen(
        [player_sim, world, "--port-base", str(port)], stderr=subprocess.DEVNULL
    )
    bridge_log = open("/tmp/player-ros2-peer.log", "w")
    name = "r0" if mode == "drive" else "nav"
    ros = subprocess.Popen([bridge, f"127.0.0.1:{port}={name}"], stderr=bridge_log)
    seen = {}
    try:
        (drive if mode == "drive" else navigate)(port, seen)
    finally:
        ros.terminate()
        sim.terminate()
        ros.wait(10)
        sim.wait(10)
        bridge_log.close()
    seen["bridge_log"] = open("/tmp/player-ros2-peer.log").read()[-4000:]
    print(json.dumps(seen))


def newest(reader):
    samples = reader.take(100)
    return samples[-1] if samples else None


def navigate(port, seen):
    nav = wait_for("player-sim", lambda: try_connect(port))
    participant = DomainParticipant(0)
    time.sleep(3.0)  # come late: the map must still be there
    maps = DataReader(participant, Topic(participant, "rt/map", OccupancyGrid), qos=LATCHED)
    grid = wait_for("the map on rt/map", lambda: next(iter(maps.take(1)), None))
    seen["map"] = {
        "width": grid.info.width,
        "height": grid.info.height,
        "resolution": grid.info.resolution,
        "origin": [grid.info.origin.position.x, grid.info.origin.position.y],
        "values": sorted(set(grid.data)),
        "corner": grid.data[0],
        "frame": grid.header.frame_id,
    }
    goals = DataWriter(participant, Topic(participant, "rt/nav/goal_pose", PoseStamped), qos=RELIABLE)
    starts = DataWriter(
        participant,
        Topic(participant, "rt/nav/initialpose", PoseWithCovarianceStamped),
        qos=RELIABLE,
    )
    wait_for("the bridge's goal reader", lambda: True if goals.get_publication_matched_status().current_count else None)
    wait_for("the bridge's start reader", lambda: True if starts.get_publication_matched_status().current_count else None)
    plans = DataReader(participant, Topic(participant, "rt/nav/plan", Path), qos=LATCHED)
    here = Header(frame_id="map")
    goals.write(PoseStamped(here, Pose(Point(3.5, 4.5, 0.0), yaw_quaternion(1.57))))
    planner = nav.planner(0)
    state = wait_for(
        "the planner's goal",
        lambda: (lambda s: s if tuple(round(v, 2) for v in s.goal[:2]) == (3.5, 4.5) else None)(
            planner.read(timeout=5.0)
        ),
    )
    seen["goal"] = list(state.goal)
    path = wait_for(
        "a path to the goal on rt/nav/plan",
        lambda: next((p for p in plans.take(10) if len(p.poses) > 1), None),
    )
    last = path.poses[-1].pose.position
    seen["plan"] = {"frame": path.header.frame_id, "poses": len(path.poses), "last": [last.x, last.y]}
    covariance = [0.0] * 36
    covariance[0] = covariance[7] = 0.1
    covariance[35] = 0.05
    start = PoseWithCovariance(Pose(Point(-6.0, -4.0, 0.0), yaw_quaternion(0.5)), covariance)
    starts.write(PoseWithCovarianceStamped(here, start))
    localize = nav.localize(0)
    estimate = wait_for(
        "the localizer's new start",
        lambda: (lambda e: e if abs(e.pose[0] + 6.0) < 0.3 and abs(e.pose[1] + 4.0) < 0.3 else None)(
            localize.read(timeout=5.0)
        ),
    )
    seen["estimate"] = list(estimate.pose)


def drive(port, seen):
    robot = wait_for("player-sim", lambda: try_connect(port))
    base = robot.position2d(0)
    participant = DomainParticipant(0)
    best_effort = Qos(Policy.Reliability.BestEffort, Policy.History.KeepLast(5))
    reliable = RELIABLE
    scans = DataReader(participant, Topic(participant, "rt/r0/scan", LaserScan), qos=best_effort)
    odometry = DataReader(participant, Topic(participant, "rt/r0/odom", Odometry), qos=reliable)
    cmd_vel = DataWriter(participant, Topic(participant, "rt/r0/cmd_vel", Twist), qos=reliable)

    wait_for("a first scan on rt/r0/scan", lambda: next(iter(scans.take(1)), None))
    seen["garbage"] = garbage_to_the_dds_ports()
    scans.take(100)
    scan = wait_for("a scan after the garbage", lambda: next(iter(scans.take(1)), None))
    seen["scan"] = {
        "beams": len(scan.ranges),
        "frame": scan.header.frame_id,
        "angle_min": scan.angle_min,
        "range_max": scan.range_max,
    }
    odom = wait_for("odometry on rt/r0/odom", lambda: next(iter(odometry.take(1)), None))
    statics = DataReader(participant, Topic(participant, "rt/tf_static", TFMessage), qos=LATCHED)
    fixed = wait_for("fixed transforms on rt/tf_static", lambda: next(iter(statics.take(1)), None))
    seen["tf_static"] = [
        [t.header.frame_id, t.child_frame_id, t.transform.translation.x]
        for t in fixed.transforms
    ]
    seen["odom"] = {
        "frame": odom.header.frame_id,
        "child": odom.child_frame_id,
        "x": odom.pose.pose.position.x,
    }

    start = base.pose
    wait_for("the bridge's cmd_vel reader", lambda: True if cmd_vel.get_publication_matched_status().current_count else None)
    for _ in range(20):  # two seconds of teleop at 10 Hz
        cmd_vel.write(Twist(linear=Vector3(x=0.5)))
        time.sleep(0.1)
    moved = base.pose
    seen["moved"] = math.hypot(moved[0] - start[0], moved[1] - start[1])

    time.sleep(1.5)  # teleop "dies": the deadline stops the robot
    before = base.pose
    time.sleep(1.0)
    after = base.pose
    seen["after_stop"] = math.hypot(after[0] - before[0], after[1] - before[1])

    for _ in range(10):
        cmd_vel.write(Twist(linear=Vector3(x=float("nan"))))
        cmd_vel.write(Twist(linear=Vector3(x=50.0)))
        time.sleep(0.1)
    later = base.pose
    seen["after_nan"] = math.hypot(later[0] - after[0], later[1] - after[1])


def try_connect(port):
    try:
        return player3.connect("127.0.0.1", port, timeout=1.0, read_only=True)
    except Exception:
        return None


if __name__ == "__main__":
    main(*sys.argv[1:5])

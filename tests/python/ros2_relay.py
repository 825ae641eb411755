"""The relay's ROS 2 front seen from a real ROS 2 peer (Cyclone DDS), for test_ros2_live.py:
`player-relay --world simple.world --ros2 --ros2-twist-stamped` in a network namespace of its
own (loopback only).

    unshare -n python ros2_relay.py PLAYER_RELAY simple.world

reads r0's scans and odometry, its laser ranger as a point cloud, and the simulation's /clock
(every scan stamped by it, not by the wall); drives r0 with Jazzy's TwistStamped and sees its
odometry say it moved; finds /r0/player and the clock's /player_relay in ros_discovery_info.
Prints what it saw as one line of JSON.
"""

import json
import math
import subprocess
import sys
import time
from dataclasses import dataclass, field

from cyclonedds.core import Policy, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import float32, sequence, uint8, uint32
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

from ros2_faults import Graph
from ros2_peer import (
    RELIABLE,
    Header,
    LaserScan,
    Odometry,
    Time,
    Twist,
    Vector3,
    loopback_with_multicast,
    wait_for,
)


@dataclass
class Clock(IdlStruct, typename="rosgraph_msgs::msg::dds_::Clock_"):
    clock: Time


@dataclass
class TwistStamped(IdlStruct, typename="geometry_msgs::msg::dds_::TwistStamped_"):
    header: Header = field(default_factory=Header)
    twist: Twist = field(default_factory=Twist)


@dataclass
class PointField(IdlStruct, typename="sensor_msgs::msg::dds_::PointField_"):
    name: str
    offset: uint32
    datatype: uint8
    count: uint32


@dataclass
class PointCloud2(IdlStruct, typename="sensor_msgs::msg::dds_::PointCloud2_"):
    header: Header
    height: uint32
    width: uint32
    fields: sequence[PointField]
    is_bigendian: bool
    point_step: uint32
    row_step: uint32
    data: sequence[uint8]
    is_dense: bool


BEST_EFFORT = Qos(Policy.Reliability.BestEffort, Policy.History.KeepLast(5))


def seconds(t):
    return t.sec + t.nanosec * 1e-9


def newest(reader):
    samples = reader.take(100)
    return samples[-1] if samples else None


def main(relay, world):
    loopback_with_multicast()
    log = open("/tmp/player-relay-peer.log", "w")
    process = subprocess.Popen(
        [relay, "--world", world, "--ros2", "--ros2-twist-stamped"], stderr=log
    )
    seen = {}
    try:
        participant = DomainParticipant(0)
        graph = Graph(participant)
        scans = DataReader(participant, Topic(participant, "rt/r0/scan", LaserScan), qos=BEST_EFFORT)
        clouds = DataReader(
            participant, Topic(participant, "rt/r0/range", PointCloud2), qos=BEST_EFFORT
        )
        clock = DataReader(participant, Topic(participant, "rt/clock", Clock), qos=RELIABLE)
        odometry = DataReader(participant, Topic(participant, "rt/r0/odom", Odometry), qos=RELIABLE)
        cmd_vel = DataWriter(
            participant, Topic(participant, "rt/r0/cmd_vel", TwistStamped), qos=RELIABLE
        )
        scan = wait_for("a scan on rt/r0/scan", lambda: newest(scans))
        seen["beams"] = len(scan.ranges)
        # The scan's stamp against the clock: the newest tick after it is no earlier, and
        # not far later (simulated time both, not the wall's).
        scan = wait_for("another scan", lambda: newest(scans))
        tick = wait_for("a tick on rt/clock", lambda: newest(clock))
        seen["scan_stamp"], seen["clock"] = seconds(scan.header.stamp), seconds(tick.clock)
        first_tick = (time.monotonic(), seen["clock"])
        cloud = wait_for("a cloud on rt/r0/range", lambda: newest(clouds))
        seen["cloud"] = {"width": cloud.width, "frame": cloud.header.frame_id}
        start = wait_for("odometry on rt/r0/odom", lambda: newest(odometry)).pose.pose.position
        wait_for(
            "the relay's cmd_vel reader",
            lambda: True if cmd_vel.get_publication_matched_status().current_count else None,
        )
        for _ in range(20):
            cmd_vel.write(TwistStamped(twist=Twist(linear=Vector3(x=0.5))))
            time.sleep(0.1)
        time.sleep(0.3)
        end = wait_for("odometry after driving", lambda: newest(odometry)).pose.pose.position
        seen["moved"] = math.hypot(end.x - start.x, end.y - start.y)
        last_tick = seconds(wait_for("a later tick", lambda: newest(clock)).clock)
        seen["clock_rate"] = (last_tick - first_tick[1]) / (time.monotonic() - first_tick[0])
        seen["nodes"] = sorted(
            wait_for(
                "the nodes in ros_discovery_info",
                lambda: (lambda n: n if "/r0/player" in n and "/player_relay" in n else None)(
                    graph.nodes()
                ),
            )
        )
    finally:
        process.terminate()
        process.wait(10)
        log.close()
    seen["relay_log"] = open("/tmp/player-relay-peer.log").read()[-3000:]
    print(json.dumps(seen))


if __name__ == "__main__":
    main(*sys.argv[1:3])

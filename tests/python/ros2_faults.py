"""Faults seen from a real ROS 2 peer, for test_ros2_live.py: Eclipse Cyclone DDS in a network
namespace of its own (loopback only), two simulated robots a and b through player-ros2 or
through player-relay's ROS 2 front.

    unshare -n python ros2_faults.py bridge PLAYER_SIM PLAYER_ROS2 simple.world
    unshare -n python ros2_faults.py relay PLAYER_SIM PLAYER_RELAY simple.world

1. a domain with no peer: the bridge runs three seconds alone and its log stays quiet;
2. ROS 2's graph: ros_discovery_info (rmw_dds_common's ParticipantEntitiesInfo, what
   `ros2 node list` reads) names the nodes /a/player and /b/player;
3. a teleop that vanishes: a process publishing a's cmd_vel at 10 Hz is killed with SIGKILL
   while a drives; a stops within the deadline and a's scans keep coming;
4. a robot that leaves: b's Player server is killed; b's topics go from discovery (the peer's
   scan reader loses its writer, its cmd_vel writer its reader) and /b/player from
   ros_discovery_info, while a stays;
5. a robot that comes back: b's server restarted on its port; the bridge reconnects, says so,
   and b's node and scans are back.

It prints what it saw as one line of JSON. `python ros2_faults.py teleop NAME` is the teleop
of step 3.
"""

import json
import math
import os
import signal
import subprocess
import sys
import time

from cyclonedds.core import Policy, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from ros2_graph import Graph
from ros2_peer import (
    RELIABLE,
    LaserScan,
    Twist,
    Vector3,
    free_port,
    loopback_with_multicast,
    try_connect,
    wait_for,
)


BEST_EFFORT = Qos(Policy.Reliability.BestEffort, Policy.History.KeepLast(5))

def teleop(name):
    """Drives robot `name` forward at 0.5 m/s, 10 Hz, until killed."""
    participant = DomainParticipant(0)
    writer = DataWriter(participant, Topic(participant, f"rt/{name}/cmd_vel", Twist), qos=RELIABLE)
    while True:
        writer.write(Twist(linear=Vector3(x=0.5)))
        time.sleep(0.1)


def start_sim(player_sim, world, port):
    return subprocess.Popen(
        [player_sim, world, "--port-base", str(port)], stderr=subprocess.DEVNULL
    )


def moving(robot, seconds=0.3):
    before = robot.position2d(0).pose
    time.sleep(seconds)
    after = robot.position2d(0).pose
    return math.hypot(after[0] - before[0], after[1] - before[1]) / seconds


def main(kind, player_sim, bridge, world):
    loopback_with_multicast()
    port_a, port_b = free_port(), free_port()
    sims = {"a": start_sim(player_sim, world, port_a), "b": start_sim(player_sim, world, port_b)}
    robot_a = wait_for("a's player-sim", lambda: try_connect(port_a))
    wait_for("b's player-sim", lambda: try_connect(port_b))
    log_path = "/tmp/player-ros2-faults.log"
    log = open(log_path, "w")
    command = {
        "bridge": [bridge, f"127.0.0.1:{port_a}=a", f"127.0.0.1:{port_b}=b"],
        # Observers on free ports: only ROS 2 matters here.
        "relay": [bridge, f"127.0.0.1:{port_a}=0=a", f"127.0.0.1:{port_b}=0=b", "--ros2"],
    }[kind]
    ros = subprocess.Popen(
        command,
        stderr=log,
        env={**os.environ, "NO_COLOR": "1"},
    )
    seen = {}
    teleop_process = None
    try:
        # 1. Nobody else in the domain.
        time.sleep(3.0)
        seen["quiet_log"] = open(log_path).read()

        participant = DomainParticipant(0)
        graph = Graph(participant)
        scans = {
            name: DataReader(
                participant, Topic(participant, f"rt/{name}/scan", LaserScan), qos=BEST_EFFORT
            )
            for name in ("a", "b")
        }
        b_cmd_vel = DataWriter(participant, Topic(participant, "rt/b/cmd_vel", Twist), qos=RELIABLE)
        for name, reader in scans.items():
            wait_for(f"{name}'s scans", lambda r=reader: r.take(10) or None)

        # 2. ROS 2's graph.
        seen["nodes"] = sorted(
            wait_for(
                "both nodes in ros_discovery_info",
                lambda: (lambda n: n if {"/a/player", "/b/player"} <= n else None)(graph.nodes()),
            )
        )

        # 3. Teleop vanishes mid-stream.
        teleop_process = subprocess.Popen([sys.executable, __file__, "teleop", "a"])
        wait_for("a driven by the teleop", lambda: True if moving(robot_a) > 0.3 else None)
        teleop_process.send_signal(signal.SIGKILL)
        teleop_process.wait(5)
        killed = time.monotonic()
        wait_for("a stopped", lambda: True if moving(robot_a, 0.1) < 0.01 else None, limit=5)
        seen["stopped_after"] = time.monotonic() - killed
        seen["still_after_2s"] = (time.sleep(1.0), moving(robot_a, 1.0))[1]
        scans["a"].take(100)
        seen["a_scans_after_teleop"] = len(
            wait_for("a's scans after the teleop died", lambda: scans["a"].take(10) or None)
        )

        # 4. Robot b leaves.
        sims["b"].send_signal(signal.SIGKILL)
        sims["b"].wait(5)
        wait_for(
            "b's scan writer gone from discovery",
            lambda: True if scans["b"].get_subscription_matched_status().current_count == 0 else None,
            limit=15,
        )
        wait_for(
            "b's cmd_vel reader gone from discovery",
            lambda: True if b_cmd_vel.get_publication_matched_status().current_count == 0 else None,
            limit=15,
        )
        seen["nodes_without_b"] = sorted(
            wait_for(
                "b's node gone from ros_discovery_info",
                lambda: (lambda n: n if "/b/player" not in n else None)(graph.nodes()),
                limit=15,
            )
        )
        seen["a_matched_without_b"] = scans["a"].get_subscription_matched_status().current_count
        scans["a"].take(100)
        seen["a_scans_without_b"] = len(
            wait_for("a's scans after b left", lambda: scans["a"].take(10) or None)
        )

        # 5. Robot b comes back on its port.
        sims["b"] = start_sim(player_sim, world, port_b)
        scans["b"].take(100)
        seen["b_back"] = len(
            wait_for("b's scans again", lambda: scans["b"].take(10) or None, limit=20)
        )
        seen["nodes_with_b_back"] = sorted(
            wait_for(
                "b's node back in ros_discovery_info",
                lambda: (lambda n: n if "/b/player" in n else None)(graph.nodes()),
            )
        )
    finally:
        if teleop_process and teleop_process.poll() is None:
            teleop_process.kill()
        ros.terminate()
        ros.wait(10)
        for sim in sims.values():
            sim.terminate()
            sim.wait(10)
        log.close()
    seen["bridge_log"] = open(log_path).read()[-4000:]
    print(json.dumps(seen))


if __name__ == "__main__":
    if sys.argv[1] == "teleop":
        teleop(sys.argv[2])
    else:
        main(*sys.argv[1:5])

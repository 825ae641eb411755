"""ROS 2's graph as a real ROS 2 peer reads it, for test_ros2_live.py: the nodes that
ros_discovery_info (rmw_dds_common's ParticipantEntitiesInfo, what `ros2 node list` reads)
names, with the ids (rmw_dds_common's Gid) as long as the ROS 2 of the reader has them — 24
bytes in Humble, 16 from Iron on (Jazzy).

    unshare -n python ros2_graph.py GID_BYTES PLAYER_SIM PLAYER_ROS2 simple.world [SECONDS]

runs player-sim and the bridge for robot `a` in a network namespace of its own and prints the
node names a reader with GID_BYTES-long ids found within SECONDS (15) or once it found the
robot's, as one line of JSON. ros2_faults.py reads
the graph through `Graph` too.
"""

import json
import subprocess
import sys
import time
from dataclasses import dataclass

from cyclonedds.core import Policy, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import array, sequence, uint8
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from ros2_peer import free_port, loopback_with_multicast, try_connect, wait_for

DISCOVERY = Qos(
    Policy.Reliability.Reliable(duration(seconds=1)),
    Policy.Durability.TransientLocal,
    Policy.History.KeepLast(1),
)


def participant_entities_info(gid_bytes):
    """rmw_dds_common's ParticipantEntitiesInfo with ids of `gid_bytes` bytes. The classes are
    made on the call, once per process: a process reads one ROS 2's layout."""

    @dataclass
    class Gid(IdlStruct, typename="rmw_dds_common::msg::dds_::Gid_"):
        data: array[uint8, gid_bytes]

    @dataclass
    class NodeEntitiesInfo(IdlStruct, typename="rmw_dds_common::msg::dds_::NodeEntitiesInfo_"):
        node_namespace: str
        node_name: str
        reader_gid_seq: sequence[Gid]
        writer_gid_seq: sequence[Gid]

    @dataclass
    class ParticipantEntitiesInfo(
        IdlStruct, typename="rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_"
    ):
        gid: Gid
        node_entities_info_seq: sequence[NodeEntitiesInfo]

    return ParticipantEntitiesInfo


class Graph:
    """The nodes ROS 2's graph says there are, from ros_discovery_info: each participant's
    newest list, kept by participant."""

    def __init__(self, participant, gid_bytes=24):
        kind = participant_entities_info(gid_bytes)
        self.reader = DataReader(participant, Topic(participant, "ros_discovery_info", kind), qos=DISCOVERY)
        self.lists = {}

    def nodes(self):
        for info in self.reader.take(100):
            self.lists[bytes(info.gid.data)] = {
                f"{n.node_namespace.rstrip('/')}/{n.node_name}"
                for n in info.node_entities_info_seq
            }
        return set().union(*self.lists.values()) if self.lists else set()


def main(gid_bytes, player_sim, bridge, world, seconds="15"):
    loopback_with_multicast()
    port = free_port()
    sim = subprocess.Popen([player_sim, world, "--port-base", str(port)], stderr=subprocess.DEVNULL)
    ros = None
    try:
        wait_for("player-sim", lambda: try_connect(port))
        ros = subprocess.Popen([bridge, f"127.0.0.1:{port}=a"], stderr=subprocess.DEVNULL)
        graph = Graph(DomainParticipant(0), int(gid_bytes))
        nodes = set()
        deadline = time.monotonic() + float(seconds)
        while "/a/player" not in nodes and time.monotonic() < deadline:
            nodes |= graph.nodes()
            time.sleep(0.1)
        print(json.dumps({"nodes": sorted(nodes)}))
    finally:
        if ros:
            ros.terminate()
            ros.wait(10)
        sim.terminate()
        sim.wait(10)


if __name__ == "__main__":
    main(*sys.argv[1:6])

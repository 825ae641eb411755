"""player-ros2 seen from a real ROS 2 peer: Eclipse Cyclone DDS (the DDS of rmw_cyclonedds_cpp,
from PyPI) in a network namespace of the test's own, loopback only, reads a simulated robot's
scans and odometry under ROS 2's names and drives it through cmd_vel — the robot moves, as
Player's own position2d says; it stops when the commands stop; a NaN or absurd command never
reaches it; garbage datagrams to the DDS ports change nothing; the laser's place on the base
is on /tf_static. On navigation.world, a late subscriber gets the map, a goal_pose reaches
Player's planner (and its path comes back on /nav/plan) and an initialpose its localizer.
Through the relay: the simulation's /clock, TwistStamped, a ranger's cloud. Faults: a quiet
domain, a teleop killed mid-stream, a robot's server killed and restarted; ROS 2's graph
(ros_discovery_info, what `ros2 node list` reads) throughout."""

import json
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def player_ros2() -> pathlib.Path:
    subprocess.run(
        ["cargo", "build", "-q", "-p", "player-ros2", "--bin", "player-ros2"], cwd=ROOT, check=True
    )
    return ROOT / "target" / "debug" / "player-ros2"


def peer(mode, world, player_sim, player_ros2):
    """What the Cyclone DDS peer saw, in a network namespace of its own."""
    return in_a_namespace(
        "ros2_peer.py", mode, player_sim, player_ros2, ROOT / "stage-worlds" / world
    )


needs_a_namespace = pytest.mark.skipif(
    os.geteuid() != 0 or shutil.which("unshare") is None,
    reason="DDS discovers by multicast: this test needs a network namespace of its own (root)",
)


@needs_a_namespace
def test_a_ros2_peer_reads_and_drives_a_player_robot(player_sim, player_ros2):
    seen = peer("drive", "simple.world", player_sim, player_ros2)
    assert seen["garbage"] >= 100, "garbage datagrams sent to the DDS ports, and it carried on"
    assert seen["scan"]["beams"] == 181 and seen["scan"]["frame"] == "r0/laser"
    assert seen["scan"]["range_max"] == 8.0
    assert (seen["odom"]["frame"], seen["odom"]["child"]) == ("r0/odom", "r0/base_link")
    assert seen["odom"]["x"] == pytest.approx(-2.0)
    # The laser 0.1 m ahead of the base, as simple.world places it.
    assert seen["tf_static"] == [["r0/base_link", "r0/laser", pytest.approx(0.1)]]
    # Two seconds at 0.5 m/s: about a metre, as Player's position2d measured it.
    assert 0.7 < seen["moved"] < 1.3, seen
    assert seen["after_stop"] < 0.01, "stopped when teleop went quiet"
    assert seen["after_nan"] < 0.01, "NaN and 50 m/s never reached the robot"
    log = seen["bridge_log"]
    assert log.count("not a number") == 1 and log.count("faster than") == 1, log
    assert "no cmd_vel for half a second: stopping" in log


@needs_a_namespace
def test_a_ros2_peer_gets_the_map_late_and_sends_a_goal_and_a_start(player_sim, player_ros2):
    seen = peer("nav", "navigation.world", player_sim, player_ros2)
    grid = seen["map"]
    assert (grid["width"], grid["height"]) == (160, 120)
    assert grid["resolution"] == pytest.approx(0.1)
    assert grid["origin"] == pytest.approx([-8.0, -6.0])
    assert grid["values"] == [0, 100] and grid["corner"] == 100, "free and walls, as ROS counts"
    assert grid["frame"] == "map"
    assert seen["goal"][:2] == pytest.approx([3.5, 4.5]), "rviz2's goal reached Player's planner"
    # The planner's path to it, asked of the planner once its plan changed.
    assert seen["plan"]["frame"] == "map" and seen["plan"]["poses"] > 1
    assert seen["plan"]["last"] == pytest.approx([3.5, 4.5], abs=0.3)
    assert seen["estimate"][:2] == pytest.approx([-6.0, -4.0], abs=0.3)


@pytest.fixture(scope="session")
def player_relay() -> pathlib.Path:
    subprocess.run(
        ["cargo", "build", "-q", "-p", "player-relay", "--bin", "player-relay"], cwd=ROOT, check=True
    )
    return ROOT / "target" / "debug" / "player-relay"


def in_a_namespace(script, *args):
    """What a peer script saw, run in a network namespace of its own."""
    done = subprocess.run(
        ["unshare", "-n", sys.executable, ROOT / "tests" / "python" / script, *args],
        capture_output=True,
        text=True,
        timeout=180,
    )
    assert done.returncode == 0, done.stderr[-3000:] + done.stdout[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


@needs_a_namespace
def test_the_relay_puts_its_robots_in_ros2_by_their_world_names_on_the_simulated_clock(
    player_relay,
):
    seen = in_a_namespace("ros2_relay.py", player_relay, ROOT / "stage-worlds" / "simple.world")
    assert seen["beams"] == 181
    # Driven through Jazzy's TwistStamped (--ros2-twist-stamped): two seconds at 0.5 m/s.
    assert 0.7 < seen["moved"] < 1.4, seen
    assert "ROS 2 node /r0/player" in seen["relay_log"], seen["relay_log"]
    # /clock is the simulation's time, and a scan is stamped by it: the tick after a scan is
    # no earlier than the scan and at most a few steps later (100 ms each).
    assert 0 < seen["scan_stamp"] <= seen["clock"] < seen["scan_stamp"] + 0.5, seen
    assert 0.5 < seen["clock_rate"] < 1.5, "simulated seconds per second, at Stage's pace"
    # The laser ranger's 181 echoes as a cloud on the base.
    assert seen["cloud"] == {"width": 181, "frame": "r0/base_link"}
    # What `ros2 node list` reads: the robot's node and the clock's.
    assert {"/r0/player", "/player_relay"} <= set(seen["nodes"]), seen["nodes"]
    assert "ERROR" not in seen["relay_log"] and "WARN" not in seen["relay_log"], seen["relay_log"]


@needs_a_namespace
@pytest.mark.parametrize("kind", ["bridge", "relay"])
def test_faults_a_quiet_domain_a_dead_teleop_a_robot_gone_and_back(
    kind, player_sim, player_ros2, player_relay
):
    program = {"bridge": player_ros2, "relay": player_relay}[kind]
    seen = in_a_namespace(
        "ros2_faults.py", kind, player_sim, program, ROOT / "stage-worlds" / "simple.world"
    )
    # Alone in the domain for three seconds: a line per robot (the relay: two, its ROS 2 node
    # and its observers' port, after the domain it joined), nothing else.
    quiet = seen["quiet_log"].splitlines()
    lines = {"bridge": 2, "relay": 5}[kind]
    assert len(quiet) == lines and not any("WARN" in l or "ERROR" in l for l in quiet), quiet
    assert seen["nodes"] == ["/a/player", "/b/player"], "ros_discovery_info, as ros2 node list"
    # The teleop killed with SIGKILL: a stopped within the half-second deadline (plus one
    # command's period and a sample), stays stopped, and its scans keep coming.
    assert seen["stopped_after"] < 1.0 and seen["still_after_2s"] < 0.01, seen
    assert seen["a_scans_after_teleop"] >= 1
    # b's server killed: its topics and node gone from discovery, a's still there.
    assert seen["nodes_without_b"] == ["/a/player"]
    assert seen["a_matched_without_b"] == 1 and seen["a_scans_without_b"] >= 1
    # b's server back on its port: the bridge reconnects and says what happened.
    assert seen["b_back"] >= 1 and seen["nodes_with_b_back"] == ["/a/player", "/b/player"]
    log = seen["bridge_log"]
    assert "b: lost its Player server (the server closed the connection)" in log, log
    assert "b: back in ROS 2 as /b/player" in log, log
    assert "a: no cmd_vel for half a second: stopping" in log, log


@pytest.fixture(scope="session")
def player_ros2_jazzy(player_ros2) -> pathlib.Path:
    """player-ros2 built with the `jazzy` feature (ROS 2's graph with Iron's 16-byte ids),
    copied aside; the plain build is put back for the other tests."""
    build = ["cargo", "build", "-q", "-p", "player-ros2", "--bin", "player-ros2"]
    subprocess.run([*build, "--features", "jazzy"], cwd=ROOT, check=True)
    jazzy = ROOT / "target" / "debug" / "player-ros2-jazzy"
    shutil.copy2(player_ros2, jazzy)
    subprocess.run(build, cwd=ROOT, check=True)
    return jazzy


@needs_a_namespace
def test_ros2_node_list_finds_the_robot_in_humbles_graph_and_with_jazzy_in_jazzys(
    player_sim, player_ros2, player_ros2_jazzy
):
    world = ROOT / "stage-worlds" / "simple.world"
    for program, gid_bytes in [(player_ros2, 24), (player_ros2_jazzy, 16)]:
        seen = in_a_namespace("ros2_graph.py", str(gid_bytes), player_sim, program, world)
        assert seen["nodes"] == ["/a/player"], (program.name, gid_bytes, seen)
    # Read with the other ROS 2's ids, a graph names nothing: the build decides who sees it.
    seen = in_a_namespace("ros2_graph.py", "16", player_sim, player_ros2, world, "5")
    assert seen["nodes"] == [], seen

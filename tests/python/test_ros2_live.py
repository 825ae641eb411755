"""player-ros2 seen from a real ROS 2 peer: Eclipse Cyclone DDS (the DDS of rmw_cyclonedds_cpp,
from PyPI) in a network namespace of the test's own, loopback only, reads a simulated robot's
scans and odometry under ROS 2's names and drives it through cmd_vel — the robot moves, as
Player's own position2d says; it stops when the commands stop; a NaN or absurd command never
reaches it; garbage datagrams to the DDS ports change nothing; the laser's place on the base
is on /tf_static. On navigation.world, a late
subscriber gets the map, a goal_pose reaches Player's planner and an initialpose its
localizer."""

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


@pytest.mark.skipif(
    os.geteuid() != 0 or shutil.which("unshare") is None,
    reason="DDS discovers by multicast: this test needs a network namespace of its own (root)",
)
def peer(mode, world, player_sim, player_ros2):
    """What the Cyclone DDS peer saw, in a network namespace of its own."""
    done = subprocess.run(
        [
            "unshare",
            "-n",
            sys.executable,
            ROOT / "tests" / "python" / "ros2_peer.py",
            mode,
            player_sim,
            player_ros2,
            ROOT / "stage-worlds" / world,
        ],
        capture_output=True,
        text=True,
        timeout=180,
    )
    assert done.returncode == 0, done.stderr[-3000:] + done.stdout[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


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
    assert seen["estimate"][:2] == pytest.approx([-6.0, -4.0], abs=0.3)


@pytest.fixture(scope="session")
def player_relay() -> pathlib.Path:
    subprocess.run(
        ["cargo", "build", "-q", "-p", "player-relay", "--bin", "player-relay"], cwd=ROOT, check=True
    )
    return ROOT / "target" / "debug" / "player-relay"


@needs_a_namespace
def test_the_relay_puts_its_robots_in_ros2_by_their_world_names(player_relay):
    seen = peer("relay", "simple.world", "-", player_relay)
    assert seen["beams"] == 181
    assert 0.7 < seen["moved"] < 1.4, seen
    assert "ROS 2 node /r0/player" in seen["relay_log"], seen["relay_log"]

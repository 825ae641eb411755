"""player-ros2 seen from a real ROS 2 peer: Eclipse Cyclone DDS (the DDS of rmw_cyclonedds_cpp,
from PyPI) in a network namespace of the test's own, loopback only, reads a simulated robot's
scans and odometry under ROS 2's names and drives it through cmd_vel — the robot moves, as
Player's own position2d says; it stops when the commands stop; a NaN or absurd command never
reaches it."""

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
def test_a_ros2_peer_reads_and_drives_a_player_robot(player_sim, player_ros2):
    done = subprocess.run(
        [
            "unshare",
            "-n",
            sys.executable,
            ROOT / "tests" / "python" / "ros2_peer.py",
            player_sim,
            player_ros2,
            ROOT / "stage-worlds" / "simple.world",
        ],
        capture_output=True,
        text=True,
        timeout=180,
    )
    assert done.returncode == 0, done.stderr[-3000:] + done.stdout[-2000:]
    seen = json.loads(done.stdout.strip().splitlines()[-1])
    assert seen["scan"]["beams"] == 181 and seen["scan"]["frame"] == "r0/laser"
    assert seen["scan"]["range_max"] == 8.0
    assert (seen["odom"]["frame"], seen["odom"]["child"]) == ("r0/odom", "r0/base_link")
    assert seen["odom"]["x"] == pytest.approx(-2.0)
    # Two seconds at 0.5 m/s: about a metre, as Player's position2d measured it.
    assert 0.7 < seen["moved"] < 1.3, seen
    assert seen["after_stop"] < 0.01, "stopped when teleop went quiet"
    assert seen["after_nan"] < 0.01, "NaN and 50 m/s never reached the robot"
    log = seen["bridge_log"]
    assert log.count("not a number") == 1 and log.count("faster than") == 1, log
    assert "no cmd_vel for half a second: stopping" in log

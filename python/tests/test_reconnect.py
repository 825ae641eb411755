"""A server restart: the robot comes back by itself, with its subscriptions."""

import subprocess
import time

import pytest

import player3
from player3_support import WORLDS, wait_listening


def test_after_a_server_restart_reads_resume_without_subscribing_again(binaries, sim_process):
    args = [WORLDS / "simple.world", "--cfg", WORLDS / "simple.cfg"]
    port, first = sim_process(*args)
    with player3.connect("127.0.0.1", port, timeout=3.0) as robot:
        laser = robot.laser(0)
        laser.read(timeout=3.0)
        first.kill()
        first.wait()
        with pytest.raises(player3.ConnectionError):
            laser.read(timeout=3.0)
        second = subprocess.Popen(
            [str(binaries["player-sim"]), *map(str, args), "--port-base", str(port)],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        try:
            wait_listening(port, second)
            robot.wait_connected(timeout=15.0)
            assert len(laser.read(timeout=5.0)) > 0
        finally:
            second.kill()
            second.wait()

"""Lockstep: simulated time advances when the program has answered, not with the wall clock;
a program's run is the same every time; connect() finds the grader's simulation in the
environment."""

import os
import subprocess
import sys
import time

import pytest

import player3
from player3_support import WORLDS


def test_a_lockstep_world_waits_for_its_program():
    with player3.simulate(WORLDS / "simple.world", lockstep=True, patience=None) as world:
        assert world.lockstep
        robot = world.robot("r0")
        laser, base = robot.laser(0), robot.position2d(0)
        first = laser.read(timeout=5.0)  # the step the world is at, sent on subscribing
        assert first.time == 0.0
        time.sleep(0.3)
        assert world.time == 0.0, "nobody commanded: the world waits"
        for step in range(1, 11):
            base.set_velocity(0.4, 0.0)
            scan = laser.read(timeout=5.0)
            assert scan.time == pytest.approx(step * 0.1)
        time.sleep(0.2)
        assert world.time == pytest.approx(1.0)
        assert base.pose[0] == pytest.approx(-2.0 + 0.4, abs=1e-6), base.pose


def test_world_step_advances_a_program_that_only_reads():
    with player3.simulate(WORLDS / "simple.world", lockstep=True, patience=None) as world:
        laser = world.robot("r0").laser(0)
        laser.read(timeout=5.0)
        assert world.step(5) == pytest.approx(0.5)
        assert world.step() == pytest.approx(0.6)


def test_step_is_refused_where_it_means_nothing():
    with player3.simulate(WORLDS / "simple.world") as world:
        assert not world.lockstep
        with pytest.raises(player3.PlayerError, match="not simulated in lockstep"):
            world.step()
    with player3.simulate(WORLDS / "simple.world", lockstep=True) as world:
        with pytest.raises(ValueError, match="steps must be 1 or more"):
            world.step(0)
    with pytest.raises(ValueError, match="patience"):
        player3.simulate(WORLDS / "simple.world", lockstep=True, patience=-1.0)


PROGRAM = """
import player3
robot = player3.connect()
laser, base = robot.laser(0), robot.position2d(0)
for _ in range(60):
    ahead = laser.read(timeout=10.0).ranges[60:120].min()
    base.set_velocity(0.0, 0.8) if ahead < 1.0 else base.set_velocity(0.5, 0.0)
laser.read(timeout=10.0)
print(*(round(v, 6) for v in base.pose))
"""


def run_program(world):
    env = dict(os.environ, PLAYER_HOST="127.0.0.1", PLAYER_PORT=str(world.ports[0]))
    done = subprocess.run(
        [sys.executable, "-c", PROGRAM], env=env, capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_a_program_run_twice_ends_in_the_same_place():
    ends = []
    for _ in range(2):
        with player3.simulate(WORLDS / "simple.world", lockstep=True, seed=4) as world:
            ends.append(run_program(world))
            assert world.time == pytest.approx(6.0)
    assert ends[0] == ends[1]
    assert ends[0].split()[:2] != ["-2.0", "0.0"], "the robot moved"


def test_connect_reads_a_bad_port_from_the_environment(monkeypatch):
    monkeypatch.setenv("PLAYER_PORT", "sixty")
    with pytest.raises(ValueError, match="PLAYER_PORT must be a port number"):
        player3.connect()

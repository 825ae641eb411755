"""Shared fixtures: the repository's paths, simulated worlds, and player-sim / playerrecord
run as separate processes (for the replay and the server killed mid-read)."""

import subprocess

import pytest

import player3
from player3_support import REPO, WORLDS, free_port, wait_listening


@pytest.fixture(scope="session")
def binaries():
    """player-sim and playerrecord, built by cargo if the test run has not built them yet."""
    subprocess.run(
        ["cargo", "build", "-q", "-p", "player-sim", "-p", "player-tools", "--bins"],
        cwd=REPO,
        check=True,
    )
    target = REPO / "target" / "debug"
    return {"player-sim": target / "player-sim", "playerrecord": target / "playerrecord"}


@pytest.fixture
def sim_process(binaries):
    """Starts `player-sim ARGS --port-base PORT` as a process; yields (port, process)."""
    started = []

    def start(*args, port_option=True):
        port = free_port()
        extra = ["--port-base", str(port)] if port_option else []
        process = subprocess.Popen(
            [str(binaries["player-sim"]), *map(str, args), *extra],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        started.append(process)
        wait_listening(port, process)
        return port, process

    yield start
    for process in started:
        process.kill()
        process.wait()


@pytest.fixture(scope="module")
def simple():
    """simple.world at ten times real time: r0 with position2d:0, ranger:0 and laser:0."""
    with player3.simulate(WORLDS / "simple.world", speedup=10.0) as world:
        yield world


@pytest.fixture
def robot(simple):
    with simple.robot("r0") as robot:
        yield robot

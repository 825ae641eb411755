"""Shared fixtures: the repository's paths, simulated worlds, and player-sim / playerrecord
run as separate processes (for the replay and the server killed mid-read)."""

import socket
import subprocess
import time
from pathlib import Path

import pytest

import player3

REPO = Path(__file__).resolve().parents[2]
WORLDS = REPO / "stage-worlds"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


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


def wait_listening(port, process, limit=20.0):
    deadline = time.monotonic() + limit
    while time.monotonic() < deadline:
        if process.poll() is not None:
            raise RuntimeError(f"server exited with {process.returncode}")
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.2).close()
            return
        except OSError:
            time.sleep(0.05)
    raise RuntimeError(f"nothing listening on {port} after {limit} s")


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

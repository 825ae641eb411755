"""Shared fixtures of the Python tests: the repository's paths and its built tools."""

import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def playerrecord() -> pathlib.Path:
    """The playerrecord binary, built (debug, as `cargo test` leaves it) if it is not fresh."""
    subprocess.run(
        ["cargo", "build", "-q", "-p", "player-tools", "--bin", "playerrecord"],
        cwd=ROOT,
        check=True,
    )
    return ROOT / "target" / "debug" / "playerrecord"


@pytest.fixture(scope="session")
def player_sim() -> pathlib.Path:
    """The player-sim binary, built (debug) if it is not fresh."""
    subprocess.run(
        ["cargo", "build", "-q", "-p", "player-sim", "--bin", "player-sim"],
        cwd=ROOT,
        check=True,
    )
    return ROOT / "target" / "debug" / "player-sim"


@pytest.fixture(scope="session")
def captures() -> list[pathlib.Path]:
    """Every capture of real Player 3 + Stage 4 traffic in the repository."""
    found = sorted((ROOT / "captures").glob("*.jsonl")) + sorted(
        (ROOT / "captures" / "nav").glob("*.jsonl")
    )
    assert len(found) >= 20, found
    return found

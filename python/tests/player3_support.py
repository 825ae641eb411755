"""Helpers the player3 tests share (a module of its own, not conftest: another test folder's
conftest.py must not shadow these names)."""

import socket
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
WORLDS = REPO / "stage-worlds"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


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

"""Against a replayed recording of a real Player + Stage server (`player-sim --replay`), and
Ctrl-C during a read that would otherwise block (a paused replay sends nothing)."""

import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import player3
from player3_support import REPO


@pytest.fixture
def recording(binaries, tmp_path):
    """captures/laser_push.jsonl (a real server's laser stream) as a recording."""
    out = tmp_path / "laser_push.prec"
    subprocess.run(
        [str(binaries["playerrecord"]), "from-capture",
         str(REPO / "captures" / "laser_push.jsonl"), "-o", str(out)],
        check=True,
        capture_output=True,
    )
    return out


def test_a_replayed_real_laser_reads_as_numpy(sim_process, recording):
    port, _ = sim_process("--replay", recording, "--loop")
    with player3.connect("127.0.0.1", port, timeout=3.0) as robot:
        assert ("laser", 0) in {(d.interface, d.index) for d in robot.devices()}
        scan = robot.laser(0).read(timeout=5.0)
        assert scan.ranges.dtype == np.float32 and len(scan) > 0
        assert np.all(scan.ranges >= 0) and np.all(scan.ranges <= scan.max_range + 1e-3)
        # A newer scan comes: the real server pushed each scan once or twice (its stamp
        # repeats), so a read may give the same stamp again, never four times over.
        assert any(robot.laser(0).read(timeout=5.0).time != scan.time for _ in range(4))


@pytest.fixture
def ctrl_c_raises():
    """Ctrl-C as at a terminal, where Python turns it into KeyboardInterrupt. A process
    started in the background by a non-interactive shell (`cmd &`: a CI runner's script can
    be one) inherits SIGINT ignored, and Python then leaves it ignored: the read would run its
    whole timeout and the test would fail for the way it was started."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


def test_ctrl_c_interrupts_a_blocking_read(sim_process, recording, ctrl_c_raises):
    port, _ = sim_process("--replay", recording, "--paused")
    with player3.connect("127.0.0.1", port, timeout=3.0) as robot:
        laser = robot.laser(0)
        threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT)).start()
        started = time.monotonic()
        with pytest.raises(KeyboardInterrupt):
            laser.read(timeout=60.0)
        assert 0.4 < time.monotonic() - started < 2


def test_timeout_zero_only_looks_and_a_paused_server_times_out(sim_process, recording):
    port, _ = sim_process("--replay", recording, "--paused")
    with player3.connect("127.0.0.1", port, timeout=3.0) as robot:
        laser = robot.laser(0)
        started = time.monotonic()
        with pytest.raises(TimeoutError, match="laser:0"):
            laser.read(timeout=0)
        with pytest.raises(TimeoutError, match="laser:0 on 127.0.0.1"):
            laser.read(timeout=0.3)
        assert time.monotonic() - started < 1.0
        assert laser.latest is None


def test_other_python_threads_run_while_a_read_waits(sim_process, recording):
    port, _ = sim_process("--replay", recording, "--paused")
    with player3.connect("127.0.0.1", port, timeout=3.0) as robot:
        laser = robot.laser(0)
        count, running = [0], [True]

        def spin():
            while running[0]:
                count[0] += 1

        spinner = threading.Thread(target=spin)
        spinner.start()
        try:
            before = count[0]
            with pytest.raises(TimeoutError):
                laser.read(timeout=0.5)
            during = count[0] - before
        finally:
            running[0] = False
            spinner.join()
        # Held, the GIL would have let the spinner run not at all during the wait.
        assert during > 10_000, during

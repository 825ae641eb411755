"""player3's read rate against the Rust client's, same run, same stream (BENCHMARKS.md).

    cargo build --release -p bench --bin laser_stream -p player-sim
    .venv/bin/python python/benches/read_rate.py

1. 361-beam laser scans pushed flat out (`laser_stream serve`): reads per second through
   `laser.read()` (touching `scan.ranges`, the numpy array) against the Rust client reading
   the same way (`laser_stream read`), alternating, five rounds each.
2. 16 robots of swarm.world (a separate player-sim), each read at its 10 Hz from its own
   Python thread: the CPU time of those Python threads (`time.thread_time`) per wall second.
"""

import subprocess
import sys
import threading
import time
from pathlib import Path

import player3

REPO = Path(__file__).resolve().parents[2]
RELEASE = REPO / "target" / "release"
SECONDS = 3.0


def python_rate(port, seconds):
    with player3.connect("127.0.0.1", port) as robot:
        laser = robot.laser(0)
        laser.read(timeout=2.0)
        reads, started = 0, time.perf_counter()
        while time.perf_counter() - started < seconds:
            scan = laser.read(timeout=2.0)
            scan.ranges
            reads += 1
        return reads / (time.perf_counter() - started)


def rust_rate(port, seconds):
    out = subprocess.run(
        [str(RELEASE / "laser_stream"), "read", str(port), str(seconds)],
        check=True, capture_output=True, text=True,
    )
    return float(out.stdout)


def flat_out():
    server = subprocess.Popen([str(RELEASE / "laser_stream"), "serve"], stdout=subprocess.PIPE,
                              text=True)
    try:
        port = int(server.stdout.readline())
        print("| Round | Rust client reads/s | player3 `.read()` reads/s | player3 ÷ Rust |")
        print("|---|---:|---:|---:|")
        for round in range(1, 6):
            rust = rust_rate(port, SECONDS)
            python = python_rate(port, SECONDS)
            print(f"| {round} | {rust:,.0f} | {python:,.0f} | {python / rust:.2f} |")
    finally:
        server.kill()
        server.wait()


def sixteen_threads(seconds=10.0, robots=16, base=7000):
    world = REPO / "stage-worlds" / "swarm.world"
    sim = subprocess.Popen(
        [str(RELEASE / "player-sim"), str(world), "--cfg", str(world.with_suffix(".cfg")),
         "--port-base", str(base)],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    )
    try:
        connections = []
        deadline = time.monotonic() + 30
        while len(connections) < robots:
            try:
                connections.append(player3.connect("127.0.0.1", base + len(connections)))
            except player3.ConnectionError:
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.2)
        cpu, reads = [0.0] * robots, [0] * robots

        def read(i):
            laser = connections[i].laser(0)
            laser.read(timeout=5.0)
            begin, started = time.thread_time(), time.monotonic()
            while time.monotonic() - started < seconds:
                scan = laser.read(timeout=5.0)
                scan.ranges.min()
                reads[i] += 1
            cpu[i] = time.thread_time() - begin

        process_begin = time.process_time()
        threads = [threading.Thread(target=read, args=(i,)) for i in range(robots)]
        started = time.monotonic()
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        wall = time.monotonic() - started
        process = time.process_time() - process_begin
        rate = sum(reads) / wall / robots
        print(f"\n{robots} robots, {robots} Python threads, {wall:.1f} s: {rate:.1f} reads/s "
              f"per robot; Python threads' CPU {sum(cpu) / wall:.3f} cores; whole client "
              f"process (with its {robots} Rust robot threads) {process / wall:.3f} cores")
        for c in connections:
            c.close()
    finally:
        sim.kill()
        sim.wait()


if __name__ == "__main__":
    flat_out()
    if "--flat-out-only" not in sys.argv:
        sixteen_threads()

"""Starts children that outlive it and busy the machine, drives a little, then hangs."""
import os
import time

import player3

for _ in range(3):
    if os.fork() == 0:
        os.setsid()  # leaves the process group
        while True:
            pass
robot = player3.connect()
base, laser = robot.position2d(0), robot.laser(0)
for _ in range(20):
    laser.read(timeout=10.0)
    base.set_velocity(0.3, 0.0)
time.sleep(10_000)

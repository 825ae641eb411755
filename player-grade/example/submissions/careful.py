"""Turns towards the charger, drives there, stops."""
import math

import player3

GOAL = (3.0, 2.0)
robot = player3.connect()
base, laser = robot.position2d(0), robot.laser(0)
while True:
    laser.read(timeout=10.0)  # the next step's scan; the pose came with it
    x, y, yaw = base.pose
    dx, dy = GOAL[0] - x, GOAL[1] - y
    if math.hypot(dx, dy) < 0.15:
        base.set_velocity(0.0, 0.0)
        break
    turn = math.atan2(dy, dx) - yaw
    turn = math.atan2(math.sin(turn), math.cos(turn))
    forward = 0.5 if abs(turn) < 0.3 else 0.0
    base.set_velocity(forward, max(-1.0, min(1.0, 2.0 * turn)))
laser.read(timeout=10.0)
print(f"arrived at ({x:.2f}, {y:.2f})")

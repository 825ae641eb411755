"""Turns on the spot for ever."""
import player3

robot = player3.connect()
base, laser = robot.position2d(0), robot.laser(0)
while True:
    laser.read(timeout=10.0)
    base.set_velocity(0.0, 1.0)

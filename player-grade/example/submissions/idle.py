"""Reads its laser and never drives."""
import player3

robot = player3.connect()
laser = robot.laser(0)
while True:
    scan = laser.read(timeout=30.0)

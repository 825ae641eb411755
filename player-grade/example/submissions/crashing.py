"""Drives for a second, then divides by zero."""
import player3

robot = player3.connect()
base, laser = robot.position2d(0), robot.laser(0)
for step in range(10):
    laser.read(timeout=10.0)
    base.set_velocity(0.5, 0.0)
print("about to divide")
print(1 / 0)

"""Full speed ahead, whatever is there."""
import player3

robot = player3.connect()
base, laser = robot.position2d(0), robot.laser(0)
for _ in range(150):
    laser.read(timeout=10.0)
    base.set_velocity(1.0, 0.0)

"""player3: talk to Player robot servers from Python 3, and simulate a Stage world in one line.

    import player3
    with player3.simulate("stage-worlds/simple.world") as world:
        robot = world.robot("r0")
        scan = robot.laser(0).read()
        print(scan.ranges.min())

The client is player-proto's Rust client (one thread per connection, reconnection with the
subscriptions restored); readings arrive as numpy arrays. See docs/PYTHON.md.
"""

from ._player3 import (
    Battery,
    Blob,
    Blobfinder,
    Bumper,
    Camera,
    ConnectionError,
    Device,
    Estimate,
    Fiducial,
    Grid,
    Gripper,
    GripperState,
    Laser,
    Localize,
    Map,
    Marker,
    PlanState,
    Planner,
    PlayerError,
    Position2d,
    Power,
    Ranger,
    RequestRefused,
    Robot,
    Scan,
    Sonar,
    Speech,
    World,
    connect,
    simulate,
)
from .frame import Frame

__all__ = [
    "Battery",
    "Blob",
    "Blobfinder",
    "Bumper",
    "Camera",
    "ConnectionError",
    "Device",
    "Estimate",
    "Fiducial",
    "Frame",
    "Grid",
    "Gripper",
    "GripperState",
    "Laser",
    "Localize",
    "Map",
    "Marker",
    "PlanState",
    "Planner",
    "PlayerError",
    "Position2d",
    "Power",
    "Ranger",
    "RequestRefused",
    "Robot",
    "Scan",
    "Sonar",
    "Speech",
    "World",
    "connect",
    "simulate",
]

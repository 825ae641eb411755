"""Type stubs for player3's compiled core (see docs/PYTHON.md)."""

import builtins
from os import PathLike
from typing import List, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

from .frame import Frame

Pose = Tuple[float, float, float]
Placement = Tuple[Pose, Tuple[float, float]]

class PlayerError(Exception):
    """Something went wrong talking to a Player server."""

class ConnectionError(builtins.ConnectionError):
    """The server cannot be reached, is not a Player server, or went away."""

class RequestRefused(PlayerError):
    """The server refused a request (a NACK, or a subscription denied)."""

def connect(
    host: Optional[str] = None,
    port: Optional[int] = None,
    timeout: float = 5.0,
    read_only: bool = False,
    name: Optional[str] = None,
) -> Robot:
    """Connects to the Player server at host:port (default: $PLAYER_HOST and $PLAYER_PORT,
    else localhost:6665); `read_only` observes only; `name` names the robot as the relay's
    fronts do (else it goes by host:port)."""

def simulate(
    world: Union[str, PathLike[str]],
    speedup: Optional[float] = None,
    lockstep: bool = False,
    patience: Optional[float] = 5.0,
    seed: int = 0,
) -> World:
    """Serves a Stage world file in this process, on free local ports; `lockstep` steps
    once every driving client has commanded (or `World.step()` says so)."""

class Device:
    """A device the server offers."""
    interface: str
    index: int
    driver: str

class World:
    """A simulated world being served; a context manager."""
    path: str
    ports: List[int]
    def robot(
        self, which: Union[str, int, None] = None, timeout: float = 5.0, read_only: bool = False
    ) -> Robot:
        """A connected Robot, by name ("r0") or by index."""
    def robots(self) -> List[str]:
        """Names of the robots, in port order."""
    lockstep: bool
    time: float
    def step(self, steps: int = 1, timeout: float = 10.0) -> float:
        """Lockstep: takes `steps` steps now, without waiting for drivers; the new time."""
    def close(self) -> None: ...
    def __enter__(self) -> World: ...
    def __exit__(self, *exc: object) -> bool: ...

class Robot:
    """A connection to one Player server; a context manager. str() is its name, else
    host:port, as the relay's fronts and logs say it."""
    address: str
    name: Optional[str]
    connected: bool
    def devices(self) -> List[Device]: ...
    def wait_connected(self, timeout: float = 10.0) -> None:
        """Waits until the connection is up again after a server restart."""
    def position2d(self, index: int = 0) -> Position2d: ...
    def laser(self, index: int = 0) -> Laser: ...
    def ranger(self, index: int = 0) -> Ranger: ...
    def sonar(self, index: int = 0) -> Sonar: ...
    def fiducial(self, index: int = 0) -> Fiducial: ...
    def camera(self, index: int = 0) -> Camera: ...
    def map(self, index: int = 0) -> Map: ...
    def localize(self, index: int = 0) -> Localize: ...
    def planner(self, index: int = 0) -> Planner: ...
    def speech(self, index: int = 0) -> Speech: ...
    def blobfinder(self, index: int = 0) -> Blobfinder: ...
    def bumper(self, index: int = 0) -> Bumper: ...
    def power(self, index: int = 0) -> Power: ...
    def gripper(self, index: int = 0) -> Gripper: ...
    def close(self) -> None: ...
    def __enter__(self) -> Robot: ...
    def __exit__(self, *exc: object) -> bool: ...
    def _repr_html_(self) -> str: ...

class Position2d:
    """A mobile base."""
    pose: Pose
    velocity: Pose
    stalled: bool
    def set_velocity(self, vx: float, vyaw: float, vy: float = 0.0) -> None: ...
    def go_to(
        self, x: float, y: float, yaw: float, timeout: Optional[float] = None,
        tolerance: float = 0.1,
    ) -> None: ...
    def stop(self) -> None: ...
    def enable_motors(self, on: bool) -> None: ...
    def geometry(self) -> Placement: ...

class Scan:
    """One reading of a range sensor."""
    ranges: npt.NDArray[np.float32]
    bearings: npt.NDArray[np.float32]
    intensities: npt.NDArray[np.float32]
    time: float
    max_range: float
    def points(self) -> npt.NDArray[np.float32]:
        """End points of the beams, N x 2, robot frame (m)."""
    def __len__(self) -> int: ...
    def _repr_png_(self) -> bytes: ...

class Laser:
    latest: Optional[Scan]
    def read(self, timeout: float = 1.0) -> Scan:
        """Waits for the next new scan."""
    def geometry(self) -> Placement: ...

class Ranger:
    latest: Optional[Scan]
    def read(self, timeout: float = 1.0) -> Scan: ...
    def geometry(self) -> Placement: ...

class Sonar:
    latest: Optional[Scan]
    def read(self, timeout: float = 1.0) -> Scan: ...
    def geometry(self) -> List[Tuple[float, float, float]]: ...

class Marker:
    id: int
    x: float
    y: float
    yaw: float

class Fiducial:
    latest: Optional[List[Marker]]
    def read(self, timeout: float = 1.0) -> List[Marker]: ...

class Blob:
    id: int
    color: int
    area: int
    x: int
    y: int
    left: int
    right: int
    top: int
    bottom: int
    range: float

class Blobfinder:
    latest: Optional[List[Blob]]
    def read(self, timeout: float = 1.0) -> List[Blob]: ...

class Bumper:
    latest: Optional[List[bool]]
    def read(self, timeout: float = 1.0) -> List[bool]: ...

class Battery:
    volts: float
    percent: float
    joules: float
    watts: float
    charging: bool

class Power:
    latest: Optional[Battery]
    def read(self, timeout: float = 1.0) -> Battery: ...

class GripperState:
    state: str
    beams: int
    stored: int

class Gripper:
    latest: Optional[GripperState]
    def read(self, timeout: float = 1.0) -> GripperState: ...
    def open(self) -> None: ...
    def close(self) -> None: ...
    def stop(self) -> None: ...

class Camera:
    latest: Optional[Frame]
    def read(self, timeout: float = 1.0) -> Frame:
        """The next frame, height x width x 3 RGB."""
    def png(self, timeout: Optional[float] = None) -> bytes: ...
    def _repr_png_(self) -> bytes: ...

class Grid:
    grid: npt.NDArray[np.int8]
    shape: Tuple[int, int]
    resolution: float
    origin: Pose
    def _repr_png_(self) -> bytes: ...

class Map:
    def read(self) -> Grid: ...

class Estimate:
    pose: Pose
    variance: Pose
    weight: float

class Localize:
    latest: Optional[Optional[Estimate]]
    def read(self, timeout: float = 1.0) -> Optional[Estimate]: ...
    def set_pose(self, x: float, y: float, yaw: float, spread: float = 0.5) -> None: ...

class PlanState:
    valid: bool
    done: bool
    pose: Pose
    goal: Pose
    waypoint: Pose
    waypoint_index: int
    waypoint_count: int

class Planner:
    latest: Optional[PlanState]
    waypoints: List[Pose]
    done: bool
    def read(self, timeout: float = 1.0) -> PlanState: ...
    def set_goal(self, x: float, y: float, yaw: float) -> None: ...

class Speech:
    def say(self, text: str) -> None: ...

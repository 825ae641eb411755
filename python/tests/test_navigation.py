"""navigation.world: map, localizer and planner on port 6665, reached through player3."""

import time

import numpy as np
import pytest

import player3
from player3_support import WORLDS


@pytest.fixture(scope="module")
def world():
    with player3.simulate(WORLDS / "navigation.world", speedup=10.0) as world:
        yield world


@pytest.fixture(scope="module")
def nav(world):
    with world.robot(0) as robot:
        yield robot


def test_r2s_blobfinder_and_gripper(world):
    with world.robot("r2") as r2:
        blobs = r2.blobfinder(0).read(timeout=5.0)
        assert isinstance(blobs, list)
        for blob in blobs:
            assert blob.left <= blob.x <= blob.right and blob.top <= blob.y <= blob.bottom
        gripper = r2.gripper(0)
        gripper.open()
        deadline = time.monotonic() + 10
        state = gripper.read(timeout=5.0)
        while state.state != "open" and time.monotonic() < deadline:
            state = gripper.read(timeout=5.0)
        assert state.state == "open", state


def test_r0s_power_pack(world):
    with world.robot("r0") as r0:
        battery = r0.power(0).read(timeout=5.0)
        assert 0 <= battery.percent <= 100 and battery.joules > 0


def test_the_map_is_the_floor_bitmap(nav):
    grid = nav.map(0).read()
    assert grid.shape == (120, 160) and grid.grid.shape == (120, 160)
    assert grid.grid.dtype == np.int8
    assert grid.resolution == pytest.approx(0.1)
    assert grid.origin[:2] == pytest.approx((-8.0, -6.0))
    cells = set(np.unique(grid.grid).tolist())
    assert cells <= {-1, 0, 1} and {-1, 1} <= cells
    # The outer wall is occupied, the start pose (-6.5, -4.5) is free.
    assert grid.grid[0, :].max() == 1
    row, col = int((-4.5 + 6.0) / 0.1), int((-6.5 + 8.0) / 0.1)
    assert grid.grid[row, col] == -1
    assert grid._repr_png_().startswith(b"\x89PNG")


def test_the_localizer_starts_where_the_config_says(nav):
    estimate = nav.localize(0).read(timeout=5.0)
    assert estimate is not None
    x, y, _ = estimate.pose
    assert (x, y) == pytest.approx((-6.5, -4.5), abs=0.5)
    nav.localize(0).set_pose(-6.5, -4.5, 0.78)


def test_a_goal_in_the_far_room_is_planned(nav):
    planner = nav.planner(0)
    planner.set_goal(3.5, 4.5, 1.57)
    state = planner.read(timeout=5.0)
    for _ in range(20):
        if state.valid and tuple(state.goal[:2]) == pytest.approx((3.5, 4.5)):
            break
        state = planner.read(timeout=5.0)
    assert state.valid, state
    waypoints = planner.waypoints
    assert len(waypoints) >= 3
    assert waypoints[-1][:2] == pytest.approx((3.5, 4.5), abs=0.1)

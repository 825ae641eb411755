"""Range readings as numpy arrays: lasers and rangers, new readings only, pictures."""

import time

import numpy as np
import pytest


def test_a_laser_scan_is_numpy_float32_with_bearings_and_points(robot):
    scan = robot.laser(0).read(timeout=2.0)
    ranges = scan.ranges
    assert isinstance(ranges, np.ndarray) and ranges.dtype == np.float32
    assert ranges.shape == (len(scan),) and len(scan) > 100
    assert np.all(ranges > 0) and np.all(ranges <= scan.max_range + 1e-3)
    bearings = scan.bearings
    assert bearings.dtype == np.float32 and bearings.shape == ranges.shape
    assert np.all(np.diff(bearings) > 0), "a fan sweeps counter-clockwise"
    points = scan.points()
    assert points.shape == (len(scan), 2)
    np.testing.assert_allclose(np.hypot(points[:, 0], points[:, 1]), ranges, rtol=1e-4)
    # The room is 10 m x 8 m: nothing is farther than its diagonal.
    assert ranges.max() < 13


def test_read_never_returns_the_same_reading_twice(robot):
    laser = robot.laser(0)
    times = [laser.read(timeout=2.0).time for _ in range(5)]
    assert all(b > a for a, b in zip(times, times[1:])), times
    assert laser.latest is not None and laser.latest.time >= times[-1]


def test_timeout_zero_takes_a_new_reading_that_is_already_there(robot):
    laser = robot.laser(0)
    first = laser.read(timeout=2.0)
    time.sleep(0.1)  # ten scans at ten times real time
    assert laser.read(timeout=0).time > first.time


def test_a_ranger_reads_like_a_laser(robot):
    ranger = robot.ranger(0)
    scan = ranger.read(timeout=2.0)
    laser_scan = robot.laser(0).read(timeout=2.0)
    assert scan.ranges.dtype == np.float32
    assert len(scan) == len(laser_scan)
    assert np.isfinite(scan.max_range)
    (x, y, yaw), (length, width) = ranger.geometry()
    assert x == pytest.approx(0.1, abs=1e-6)  # the lidar's pose on r0 in simple.world


def test_a_scan_shows_itself_as_a_png(robot):
    png = robot.laser(0).read(timeout=2.0)._repr_png_()
    assert png.startswith(b"\x89PNG\r\n\x1a\n") and len(png) > 200

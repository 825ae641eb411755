"""multirobot.world: cameras (raw and JPEG) as numpy images, fiducials, a sonar-ring
ranger, several robots."""

import numpy as np
import pytest

import player3
from player3_support import WORLDS


@pytest.fixture(scope="module")
def r0():
    with player3.simulate(WORLDS / "multirobot.world", speedup=5.0) as world:
        with world.robot("r0") as robot:
            yield robot


@pytest.mark.parametrize("index", [0, 1])  # camera:0 raw RGB, camera:1 JPEG
def test_a_camera_frame_is_height_by_width_by_3_uint8(r0, index):
    frame = r0.camera(index).read(timeout=5.0)
    assert frame.dtype == np.uint8 and frame.ndim == 3 and frame.shape[2] == 3
    assert frame.shape[0] > 10 and frame.shape[1] > 10
    assert frame.std() > 1, "a picture of the world, not one colour"
    assert r0.camera(index)._repr_png_().startswith(b"\x89PNG")
    # The frame itself shows as a picture in a notebook, and its PNG holds the same pixels.
    png = frame._repr_png_()
    assert png.startswith(b"\x89PNG") and isinstance(frame, player3.Frame)
    assert png[16:24] == frame.shape[1].to_bytes(4, "big") + frame.shape[0].to_bytes(4, "big")


def test_raw_and_jpeg_frames_show_the_same_view(r0):
    raw = r0.camera(0).read(timeout=5.0).astype(float)
    jpeg = r0.camera(1).read(timeout=5.0).astype(float)
    assert raw.shape == jpeg.shape
    assert np.abs(raw - jpeg).mean() < 30


def test_fiducials_are_markers_with_ids_and_positions(r0):
    markers = r0.fiducial(0).read(timeout=5.0)
    assert isinstance(markers, list)
    for m in markers:
        assert isinstance(m.id, int) and np.isfinite([m.x, m.y, m.yaw]).all()
        assert 0 < np.hypot(m.x, m.y) < 10


def test_a_sonar_ring_ranger_points_each_beam_its_own_way(r0):
    ring = r0.ranger(1)
    scan = ring.read(timeout=5.0)
    assert len(scan) == 8
    # The ring in robots.inc: transducers every 45 degrees, 0 first.
    assert np.degrees(scan.bearings[:3]) == pytest.approx([0, 45, 90], abs=0.5)
    points = scan.points()
    assert points.shape == (8, 2)
    assert np.all(np.hypot(points[:, 0], points[:, 1]) >= scan.ranges - 1e-3)

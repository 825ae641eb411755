"""`playerrecord export --rosbag2` read by ROS 2's own readers from PyPI, which nobody here
wrote: rosbags opens the folder, every message deserializes and serializes back to exactly
our bytes (rosbags' CDR is the reference, for Humble's and Jazzy's types), MCAP's ROS 2
decoder reads every message from its ros2msg schema, and what the messages say is what the
real Player servers of the captures sent."""

import collections
import math
import pathlib
import struct
import subprocess

import pytest
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
from rosbags.rosbag2 import Reader
from rosbags.typesys import Stores, get_typestore

from test_mcap_export import read_prec

LASER, POSITION2D, LOCALIZE, CAMERA = 6, 4, 25, 40
ROOT = pathlib.Path(__file__).resolve().parents[2]


def export(playerrecord, captures, tmp: pathlib.Path):
    prec, bag = tmp / "real.prec", tmp / "bag"
    subprocess.run(
        [playerrecord, "from-capture", "-o", prec, *captures], check=True, capture_output=True
    )
    done = subprocess.run(
        [playerrecord, "export", "--rosbag2", prec, "-o", bag, "--name", "localhost:6665=r0"],
        check=True,
        capture_output=True,
        text=True,
    )
    assert "ROS 2 messages" in done.stderr, done.stderr
    return read_prec(prec), bag


def player_data(records):
    """How many DATA messages the servers sent, by (port, interface, index, subtype)."""
    counts = collections.Counter()
    ports = {}
    for kind, direction, connection, _, data in records:
        if kind == "connection":
            ports[connection] = struct.unpack(">H", data[:2])[0]
        if kind == "message" and direction == 0:
            _, _, interf, index, msg_type, subtype = struct.unpack(">6I", data[:24])
            if msg_type == 1:
                counts[(ports[connection], interf, index, subtype)] += 1
    return counts


def test_rosbags_reads_every_message_back_to_our_bytes(playerrecord, captures, tmp_path):
    _, bag = export(playerrecord, captures, tmp_path)
    for store in (Stores.ROS2_HUMBLE, Stores.ROS2_JAZZY):
        typestore = get_typestore(store)
        seen = 0
        with Reader(bag) as reader:
            for connection, _, raw in reader.messages():
                message = typestore.deserialize_cdr(raw, connection.msgtype)
                assert bytes(typestore.serialize_cdr(message, connection.msgtype)) == bytes(raw), (
                    connection.topic
                )
                seen += 1
            assert seen == reader.message_count > 1000


def test_the_messages_say_what_the_player_servers_sent(playerrecord, captures, tmp_path):
    records, bag = export(playerrecord, captures, tmp_path)
    sent = player_data(records)
    typestore = get_typestore(Stores.ROS2_HUMBLE)
    by_topic = collections.defaultdict(list)
    with Reader(bag) as reader:
        types = {c.topic: c.msgtype for c in reader.connections}
        for connection, stamp, raw in reader.messages():
            by_topic[connection.topic].append(typestore.deserialize_cdr(raw, connection.msgtype))
    assert types["/r0/scan"] == "sensor_msgs/msg/LaserScan"
    assert types["/r0/odom"] == "nav_msgs/msg/Odometry"
    assert types["/tf"] == "tf2_msgs/msg/TFMessage"
    assert types["/r0/amcl_pose"] == "geometry_msgs/msg/PoseWithCovarianceStamped"
    assert types["/r0/plan"] == "nav_msgs/msg/Path"
    # A scan per laser scan sent (subtype 1 scans, 2 scans with a pose), an odometry and a
    # transform per position2d state.
    assert len(by_topic["/r0/scan"]) == sent[(6665, LASER, 0, 1)] + sent[(6665, LASER, 0, 2)]
    assert len(by_topic["/r0/odom"]) == sent[(6665, POSITION2D, 0, 1)]
    odometry = sum(len(v) for t, v in by_topic.items() if t.endswith("/odom") or "/odom_" in t)
    assert len(by_topic["/tf"]) == odometry
    scan = by_topic["/r0/scan"][0]
    assert len(scan.ranges) == 181 and scan.header.frame_id == "r0/laser"
    assert scan.angle_min == pytest.approx(-math.pi / 2, abs=1e-3)
    assert scan.angle_max == pytest.approx(math.pi / 2, abs=1e-3)
    # Bearings as every Player client computes them, min_angle + i x resolution: Stage says
    # a 180-degree, 181-beam laser's resolution is pi/181.
    assert scan.angle_increment == pytest.approx(math.pi / 181, abs=1e-6)
    assert all(0 <= r <= scan.range_max for r in scan.ranges)
    for odom in by_topic["/r0/odom"]:
        q = odom.pose.pose.orientation
        assert q.x**2 + q.y**2 + q.z**2 + q.w**2 == pytest.approx(1.0)
        assert (odom.header.frame_id, odom.child_frame_id) == ("r0/odom", "r0/base_link")
    amcl = by_topic["/r0/amcl_pose"][0]
    cov = amcl.pose.covariance.reshape(6, 6)
    assert (cov == cov.T).all() and cov[0, 0] > 0 and cov[5, 5] > 0
    assert amcl.header.frame_id == "map"
    # Pictures: camera 0's raw ones as Image, camera 1's JPEGs (Player's cameracompress) as
    # CompressedImage, one per picture sent.
    assert types["/r0/image_raw"] == "sensor_msgs/msg/Image"
    assert types["/r0/image_raw_1/compressed"] == "sensor_msgs/msg/CompressedImage"
    assert len(by_topic["/r0/image_raw"]) == sent[(6665, CAMERA, 0, 1)] > 0
    assert len(by_topic["/r0/image_raw_1/compressed"]) == sent[(6665, CAMERA, 1, 1)] > 0
    image = by_topic["/r0/image_raw"][0]
    assert image.encoding in ("rgb8", "mono8") and image.step * image.height == len(image.data)
    jpeg = by_topic["/r0/image_raw_1/compressed"][0]
    assert jpeg.format == "jpeg" and bytes(jpeg.data[:2]) == b"\xff\xd8"
    plans = by_topic["/r0/plan"]
    assert any(len(p.poses) > 1 for p in plans) and all(p.header.frame_id == "map" for p in plans)
    # Beside each picture, its size (uncalibrated: Player says nothing of the lens).
    assert types["/r0/camera_info"] == "sensor_msgs/msg/CameraInfo"
    assert len(by_topic["/r0/camera_info"]) == len(by_topic["/r0/image_raw"])
    info = by_topic["/r0/camera_info"][0]
    assert (info.width, info.height) == (image.width, image.height) and not info.k.any()
    # The map a client read tile by tile (captures/nav/map_info_data): one whole grid, its
    # 1681 walls and 23919 free cells as navclient counted them.
    assert types["/map"] == "nav_msgs/msg/OccupancyGrid"
    (grid,) = by_topic["/map"]
    assert (grid.info.width, grid.info.height, grid.header.frame_id) == (160, 160, "map")
    assert grid.info.resolution == pytest.approx(0.1)
    assert (grid.info.origin.position.x, grid.info.origin.position.y) == (-8.0, -8.0)
    cells = collections.Counter(int(c) for c in grid.data)
    assert cells == {100: 1681, 0: 23919}


def free_port():
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_a_recorded_simulation_s_rangers_become_point_clouds(playerrecord, player_sim, tmp_path):
    """multirobot.world recorded by playerrecord (which asks every ranger its geometry and
    configuration): r0's laser ranger (181 beams) and its ring of 8 sonars as clouds in
    r0/base_link."""
    port = free_port()
    sim = subprocess.Popen(
        [player_sim, ROOT / "stage-worlds" / "multirobot.world", "--port-base", str(port)],
        stderr=subprocess.DEVNULL,
    )
    try:
        prec = tmp_path / "sim.prec"
        # Four seconds: a debug player-sim on a loaded CI machine once sent nothing in two.
        subprocess.run(
            [playerrecord, "record", f"localhost:{port}", "-o", prec, "-t", "4"],
            check=True,
            capture_output=True,
            timeout=30,
        )
    finally:
        sim.terminate()
        sim.wait(10)
    bag = tmp_path / "bag"
    subprocess.run(
        [playerrecord, "export", "--rosbag2", prec, "-o", bag, "--name", f"localhost:{port}=r0"],
        check=True,
        capture_output=True,
    )
    typestore = get_typestore(Stores.ROS2_JAZZY)
    clouds = collections.defaultdict(list)
    with Reader(bag) as reader:
        for connection, _, raw in reader.messages():
            if connection.msgtype == "sensor_msgs/msg/PointCloud2":
                clouds[connection.topic].append(typestore.deserialize_cdr(raw, connection.msgtype))
    assert set(clouds) == {"/r0/range", "/r0/range_1"}, clouds.keys()
    for topic, beams in (("/r0/range", 181), ("/r0/range_1", 8)):
        cloud = clouds[topic][-1]
        assert cloud.header.frame_id == "r0/base_link"
        assert [f.name for f in cloud.fields] == ["x", "y", "z", "range"]
        points = [struct.unpack_from("<4f", bytes(cloud.data), i * 16) for i in range(cloud.width)]
        assert cloud.width == beams
        # Each echo lies its range away from its transducer, which stands on the robot.
        for x, y, _, r in points:
            assert 0 < r <= 8.0 and abs(math.hypot(x, y) - r) < 0.5, (topic, x, y, r)
    # The sonars face every way round the robot; the laser ranger looks ahead.
    ring = clouds["/r0/range_1"][-1]
    bearings = {
        round(math.degrees(math.atan2(*struct.unpack_from("<2f", bytes(ring.data), i * 16)[::-1])))
        for i in range(ring.width)
    }
    assert max(bearings) - min(bearings) > 270, bearings
    # The first sonar, 0.2 m ahead of the ranger facing forward: its echo straight ahead.
    x, y, _, r = struct.unpack_from("<4f", bytes(ring.data), 0)
    assert abs(y) < 0.05 and x == pytest.approx(r + 0.2, abs=0.1), (x, y, r)


def test_mcap_ros2_decodes_every_message_and_the_metadata_adds_up(playerrecord, captures, tmp_path):
    _, bag = export(playerrecord, captures, tmp_path)
    files = list(bag.glob("*.mcap"))
    assert [f.name for f in files] == ["bag_0.mcap"]
    with open(files[0], "rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        assert reader.get_header().profile == "ros2"
        decoded = collections.Counter(
            channel.topic for _, channel, _, _ in reader.iter_decoded_messages()
        )
    metadata = (bag / "metadata.yaml").read_text()
    assert "storage_identifier: mcap" in metadata
    assert f"message_count: {sum(decoded.values())}" in metadata
    for topic, count in decoded.items():
        assert f"name: {topic}\n" in metadata and f"message_count: {count}\n" in metadata

"""`playerrecord export --mcap` read by the `mcap` reader from PyPI, which nobody here wrote:
every record of a recording of real Player servers is a message on its connection's channel,
with its schema and its exact bytes, and the Foxglove channels decode with their protobuf
schemas to what the Player messages said."""

import collections
import pathlib
import struct
import subprocess
import zlib

from mcap.reader import make_reader
from mcap_protobuf.decoder import DecoderFactory

KINDS = {1: "connection", 2: "opened", 3: "message", 4: "closed"}


def read_prec(path: pathlib.Path):
    """The records of a .prec, by the format's description (docs/RECORDING-FORMAT.md):
    (kind, direction, connection, time_ns, data)."""
    raw = path.read_bytes()
    assert raw[:8] == b"\x89PLAYREC" and struct.unpack(">I", raw[8:12]) == (1,)
    at, records = 12, []
    while at < len(raw):
        (length,) = struct.unpack(">I", raw[at : at + 4])
        payload = raw[at + 4 : at + 4 + length]
        (crc,) = struct.unpack(">I", raw[at + 4 + length : at + 8 + length])
        assert zlib.crc32(payload) == crc
        kind, direction, connection, time_ns = struct.unpack(">BBxxIQ", payload[:16])
        records.append((KINDS[kind], direction, connection, time_ns, payload[16:]))
        at += 8 + length
    return records


def export(playerrecord, captures, tmp: pathlib.Path):
    prec, mcap = tmp / "real.prec", tmp / "real.mcap"
    subprocess.run(
        [playerrecord, "from-capture", "-o", prec, *captures], check=True, capture_output=True
    )
    subprocess.run(
        [playerrecord, "export", "--mcap", prec, "-o", mcap], check=True, capture_output=True
    )
    return read_prec(prec), mcap


def topic_of(kind, direction, connection):
    stream = "session" if kind != "message" else ("to_server" if direction else "to_client")
    return f"/player/{connection}/{stream}"


def test_every_record_is_a_message_with_its_schema_and_its_bytes(playerrecord, captures, tmp_path):
    records, mcap = export(playerrecord, captures, tmp_path)
    with open(mcap, "rb") as f:
        reader = make_reader(f)
        summary = reader.get_summary()
        raw = [
            (schema.name, channel.topic, message)
            for schema, channel, message in reader.iter_messages(log_time_order=False)
            if channel.topic.startswith("/player/")
        ]
    want = collections.Counter(topic_of(k, d, c) for k, d, c, _, _ in records)
    got = collections.Counter(topic for _, topic, _ in raw)
    assert got == want
    # The statistics an MCAP writer keeps agree with what is there.
    counts = summary.statistics.channel_message_counts
    by_topic = {c.topic: counts.get(i, 0) for i, c in summary.channels.items()}
    assert {t: n for t, n in by_topic.items() if t.startswith("/player/")} == dict(want)
    # In the recording's order, each message: its schema, its time, its bytes.
    for (kind, _, _, time_ns, data), (schema, _, message) in zip(records, raw, strict=True):
        assert message.log_time == time_ns
        if kind == "message":
            assert schema == "player.Message"
            assert message.data == data
        else:
            assert schema == "player.Session"
            assert f'"event":"{kind}"'.encode() in message.data
    # Foxglove's side: every channel has a well-known protobuf schema.
    schemas = {summary.schemas[c.schema_id].name for c in summary.channels.values()}
    for name in ["LaserScan", "PoseInFrame", "FrameTransform", "Grid", "RawImage",
                 "CompressedImage", "SceneUpdate", "Log"]:
        assert f"foxglove.{name}" in schemas, schemas
    for channel in summary.channels.values():
        if not channel.topic.startswith("/player/"):
            assert summary.schemas[channel.schema_id].encoding == "protobuf"
            assert channel.message_encoding == "protobuf"


def laser_ranges(body: bytes):
    """A Player laser scan body (XDR): min/max angle, resolution, max range, then the ranges
    count and the ranges as an XDR array (its own count, then big-endian floats)."""
    min_angle, max_angle, _, _, count, array = struct.unpack(">ffffII", body[:24])
    assert count == array
    return min_angle, max_angle, list(struct.unpack(f">{count}f", body[24 : 24 + 4 * count]))


def test_laser_scans_decode_to_the_player_ranges(playerrecord, captures, tmp_path):
    laser = [c for c in captures if c.name == "laser_push.jsonl"]
    records, mcap = export(playerrecord, laser, tmp_path)
    sent = []
    for kind, direction, _, _, data in records:
        if kind != "message" or direction != 0:
            continue
        interf, _, msg_type, subtype = struct.unpack(">IIII", data[8:24])
        if (interf, msg_type, subtype) == (6, 1, 1):  # laser, DATA, scan
            sent.append(laser_ranges(data[40:]))
    assert len(sent) >= 10
    with open(mcap, "rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        decoded = [
            (schema.name, proto)
            for schema, _, _, proto in reader.iter_decoded_messages(
                topics=["/localhost:6665/laser/0/scan"], log_time_order=False
            )
        ]
    assert len(decoded) == len(sent)
    for (schema, scan), (min_angle, max_angle, ranges) in zip(decoded, sent, strict=True):
        assert schema == "foxglove.LaserScan"
        assert scan.frame_id == "localhost:6665/laser/0"
        assert scan.start_angle == min_angle and scan.end_angle == max_angle
        assert list(scan.ranges) == ranges

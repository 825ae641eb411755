"""`playerrecord record -o run.mcap` against a live player-sim: the file is MCAP (the name
chose it), read by the `mcap` reader from PyPI; it holds the raw session and the Foxglove
frame tree world → robot → sensor built from the geometries playerrecord asked for."""

import socket
import subprocess

from mcap.reader import make_reader
from mcap_protobuf.decoder import DecoderFactory

from conftest import ROOT


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_a_live_recording_named_mcap_is_mcap_with_its_frame_tree(
    playerrecord, player_sim, tmp_path
):
    port = free_port()
    sim = subprocess.Popen(
        [player_sim, ROOT / "stage-worlds" / "simple.world", "--port-base", str(port)],
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        for line in sim.stderr:
            if "serving" in line:
                break
        out = tmp_path / "live.mcap"
        subprocess.run(
            [playerrecord, "record", f"127.0.0.1:{port}", "-o", out, "-t", "2"],
            check=True,
            capture_output=True,
            timeout=60,
        )
    finally:
        sim.terminate()
        sim.wait()
    assert out.read_bytes()[:8] == b"\x89MCAP0\r\n"
    robot = f"127.0.0.1:{port}"
    with open(out, "rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        transforms = {
            (t.parent_frame_id, t.child_frame_id)
            for _, _, _, t in reader.iter_decoded_messages(topics=[f"/{robot}/tf"])
        }
    assert ("world", robot) in transforms, transforms
    assert (robot, f"{robot}/laser/0") in transforms, transforms
    assert (robot, f"{robot}/ranger/0") in transforms, transforms
    with open(out, "rb") as f:
        summary = make_reader(f).get_summary()
    topics = {c.topic for c in summary.channels.values()}
    assert {"/player/0/to_client", "/player/0/to_server", "/player/0/session"} <= topics
    assert f"/{robot}/laser/0/scan" in topics

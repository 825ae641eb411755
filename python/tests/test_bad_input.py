"""Bad input gives a clear Python exception naming what and where, within the timeout:
never a crash of the interpreter, never a hang."""

import socket
import threading
import time

import pytest

import player3
from player3_support import WORLDS, free_port


def test_a_closed_port_is_a_connection_error_naming_it():
    port = free_port()
    started = time.monotonic()
    with pytest.raises(player3.ConnectionError, match=f"127.0.0.1:{port}"):
        player3.connect("127.0.0.1", port, timeout=1.0)
    assert time.monotonic() - started < 5


def test_a_server_that_is_not_player_is_a_connection_error_within_the_timeout():
    listener = socket.socket()
    listener.bind(("127.0.0.1", 0))
    listener.listen()
    port = listener.getsockname()[1]

    def answer_like_a_web_server():
        conn, _ = listener.accept()
        conn.sendall(b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n" * 4)
        time.sleep(3)
        conn.close()

    threading.Thread(target=answer_like_a_web_server, daemon=True).start()
    started = time.monotonic()
    with pytest.raises(player3.ConnectionError, match=str(port)):
        player3.connect("127.0.0.1", port, timeout=1.0)
    assert time.monotonic() - started < 4
    listener.close()


def test_a_device_the_server_lacks_is_a_key_error_listing_what_it_has(robot):
    with pytest.raises(KeyError, match="sonar:0 is not on .*laser:0"):
        robot.sonar(0)
    with pytest.raises(KeyError, match="laser:3"):
        robot.laser(3)


def test_an_index_out_of_range_is_a_value_error(robot):
    with pytest.raises(ValueError, match="-1"):
        robot.laser(-1)
    with pytest.raises(ValueError, match="70000"):
        robot.position2d(70000)


def test_a_negative_or_nan_timeout_is_a_value_error(robot):
    laser = robot.laser(0)
    for bad in (-1.0, float("nan")):
        with pytest.raises(ValueError, match="timeout"):
            laser.read(timeout=bad)
    with pytest.raises(ValueError, match="timeout"):
        player3.connect("127.0.0.1", 1, timeout=-2)
    with pytest.raises(ValueError, match="timeout of 0"):
        player3.connect("127.0.0.1", 1, timeout=0)


def test_wrong_argument_types_are_type_errors(robot):
    with pytest.raises(TypeError):
        robot.laser("zero")
    with pytest.raises(TypeError):
        robot.position2d(0).set_velocity("fast", 0)
    with pytest.raises(TypeError):
        robot.laser(0).read(timeout="soon")
    with pytest.raises(ValueError, match="port"):
        player3.connect("127.0.0.1", 70000)
    with pytest.raises(FileNotFoundError, match="nowhere.world"):
        player3.simulate("nowhere.world")


def test_a_server_killed_in_the_middle_of_a_read_is_a_connection_error(sim_process):
    port, process = sim_process(WORLDS / "simple.world", "--cfg", WORLDS / "simple.cfg")
    with player3.connect("127.0.0.1", port, timeout=3.0) as robot:
        laser = robot.laser(0)
        laser.read(timeout=3.0)
        threading.Timer(0.3, process.kill).start()
        started = time.monotonic()
        with pytest.raises(player3.ConnectionError, match=str(port)):
            while True:  # readings until the server dies
                laser.read(timeout=5.0)
        assert time.monotonic() - started < 5
        assert not robot.connected

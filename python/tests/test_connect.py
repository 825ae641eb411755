"""Connecting, the device list, context managers, read-only observers, several threads."""

import threading

import pytest

import player3
from player3_support import WORLDS


def test_a_robot_lists_its_devices_with_their_drivers(robot):
    devices = robot.devices()
    names = {(d.interface, d.index) for d in devices}
    assert {("position2d", 0), ("ranger", 0), ("laser", 0)} <= names
    laser = next(d for d in devices if d.interface == "laser")
    assert laser.driver == "rangertolaser"
    assert robot.connected


def test_connect_reaches_a_served_port_and_closes_with_the_block(simple):
    port = simple.ports[0]
    with player3.connect("127.0.0.1", port, timeout=2.0) as robot:
        assert robot.address == f"127.0.0.1:{port}"
        assert robot.position2d(0).pose is not None
    with pytest.raises(player3.ConnectionError, match="closed"):
        robot.devices()


def test_a_read_only_robot_reads_but_refuses_to_drive(simple):
    with simple.robot("r0", read_only=True) as observer:
        assert len(observer.laser(0).read(timeout=2.0)) > 0
        with pytest.raises(PermissionError, match="read-only"):
            observer.position2d(0).set_velocity(0.2, 0.0)


def test_robots_are_named_or_counted(simple):
    assert simple.robots() == ["r0"]
    with pytest.raises(KeyError, match="r9"):
        simple.robot("r9")
    with pytest.raises(KeyError, match="1 robots"):
        simple.robot(3)
    with pytest.raises(TypeError):
        simple.robot(1.5)


def test_a_robot_goes_by_its_name_as_the_fronts_say_it(simple):
    port = simple.ports[0]
    with simple.robot("r0") as by_name, simple.robot(0) as by_index:
        assert by_name.name == by_index.name == "r0"
        assert str(by_name) == "r0"
        assert repr(by_name).startswith(f"<Robot r0 at 127.0.0.1:{port} (connected")
    with player3.connect("127.0.0.1", port, timeout=2.0) as unnamed:
        assert unnamed.name is None
        assert str(unnamed) == f"127.0.0.1:{port}"
    with player3.connect("127.0.0.1", port, timeout=2.0, name="scout-1") as named:
        assert (named.name, str(named)) == ("scout-1", "scout-1")
    with pytest.raises(ValueError, match="bad robot name"):
        player3.connect("127.0.0.1", port, name="two words")


def test_several_robots_read_from_several_threads_at_once():
    with player3.simulate(WORLDS / "multirobot.world", speedup=5.0) as world:
        robots = [world.robot(i) for i in range(len(world.ports))]
        assert len(robots) >= 2
        scans = {}
        errors = []

        def read_from(i, robot):
            try:
                laser = robot.laser(0)
                scans[i] = [len(laser.read(timeout=3.0)) for _ in range(5)]
            except Exception as e:  # reported below, with the robot
                errors.append((i, e))

        threads = [threading.Thread(target=read_from, args=p) for p in enumerate(robots)]
        for t in threads:
            t.start()
        for t in threads:
            t.join(timeout=30)
        assert not errors, errors
        assert sorted(scans) == list(range(len(robots)))
        assert all(n > 0 for counts in scans.values() for n in counts)
        for r in robots:
            r.close()


def test_a_robot_shows_itself_as_a_table_of_devices(robot):
    robot.laser(0).read(timeout=2.0)
    html = robot._repr_html_()
    assert "<table>" in html and "laser:0" in html and "rangertolaser" in html
    assert "s ago" in html  # the laser has sent something

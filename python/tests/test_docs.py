"""Every example in docs/PYTHON.md runs, from the repository root, and does what it says."""

import os
import re

import pytest

from player3_support import REPO

PAGE = REPO / "docs" / "PYTHON.md"


def examples():
    return re.findall(r"```python\n(.*?)```", PAGE.read_text(), flags=re.S)


def run(source):
    namespace = {"__name__": "docs_example"}
    here = os.getcwd()
    os.chdir(REPO)
    try:
        exec(compile(source, str(PAGE), "exec"), namespace)
    finally:
        os.chdir(here)
    return namespace


def test_the_page_has_its_examples():
    assert len(examples()) >= 6


@pytest.mark.parametrize("index", range(len(examples())))
def test_each_example_runs(index, capsys):
    namespace = run(examples()[index])
    out = capsys.readouterr().out
    source = examples()[index]
    if "follow_wall(robot, 3.0)" in source:
        # The wall follower covered 3 m without a stall (it raises on one).
        assert namespace["covered"] >= 3.0
    if "base.go_to(" in source:
        x, y, _ = eval(out.split("arrived at")[1])
        assert abs(x + 1.0) <= 0.1 and abs(y - 1.0) <= 0.1, out
    if "planner.set_goal" in source:
        assert "reached the goal: True" in out, out
    if "print(world.robots())" in source:
        assert "['r0']" in out and "laser 0 rangertolaser" in out
    if "def describe" in source:
        assert callable(namespace["describe"])


def test_describe_works_against_a_server_over_tcp(simple):
    namespace = run(next(e for e in examples() if "def describe" in e))
    devices = namespace["describe"]("127.0.0.1", simple.ports[0])
    assert ("laser", 0) in devices

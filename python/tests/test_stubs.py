"""The type stubs name what the module has: every class, function and method, both ways."""

import ast
from pathlib import Path

import player3
from player3 import _player3

STUBS = Path(player3.__file__).with_name("_player3.pyi")


def stubbed():
    tree = ast.parse(STUBS.read_text())
    names = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            names[node.name] = set()
        elif isinstance(node, ast.ClassDef):
            members = set()
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    members.add(item.name)
                elif isinstance(item, ast.AnnAssign):
                    members.add(item.target.id)
            names[node.name] = members
    return names


def test_every_name_of_the_module_is_in_the_stubs_and_back():
    stubs = stubbed()
    public = {n for n in dir(_player3) if not n.startswith("_")}
    assert public == set(stubs), (public ^ set(stubs))
    for name, members in stubs.items():
        thing = getattr(_player3, name)
        missing = {m for m in members if not hasattr(thing, m)}
        assert not missing, f"{name} lacks {missing}"
        if isinstance(thing, type) and not issubclass(thing, BaseException):
            own = {m for m in vars(thing) if not m.startswith("_")}
            assert own <= members, f"{name}: not in the stubs: {own - members}"


def test_every_public_name_has_a_docstring():
    for name in player3.__all__:
        thing = getattr(player3, name)
        assert (thing.__doc__ or "").strip(), name

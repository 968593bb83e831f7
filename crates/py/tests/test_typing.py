"""The type stub covers the module: every public name and every public member of its classes."""

import ast
from pathlib import Path

import pytest

import ballscrew

STUB = Path(ballscrew.__file__).with_name("_ballscrew.pyi")


def stub_tree():
    return ast.parse(STUB.read_text())


def test_stub_and_marker_ship_with_the_package():
    assert STUB.is_file()
    assert STUB.with_name("py.typed").is_file()


def test_stub_lists_every_public_name():
    tree = stub_tree()
    declared = {n.name for n in tree.body if isinstance(n, (ast.ClassDef, ast.FunctionDef))}
    exported = next(
        ast.literal_eval(n.value) for n in tree.body
        if isinstance(n, ast.Assign) and any(getattr(t, "id", "") == "__all__" for t in n.targets)
    )
    assert set(ballscrew.__all__) == set(exported) == declared


@pytest.mark.parametrize("name", ["Screw", "Evaluator", "Reversal"])
def test_stub_covers_every_member_of_the_classes(name):
    cls = next(n for n in stub_tree().body if isinstance(n, ast.ClassDef) and n.name == name)
    stubbed = {n.name for n in cls.body if isinstance(n, ast.FunctionDef) and not n.name.startswith("_")}
    public = {member for member in dir(getattr(ballscrew, name)) if not member.startswith("_")}
    assert public == stubbed

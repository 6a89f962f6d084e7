"""The generated type stubs (build/python/mocap.pyi) parse and name everything the module has."""

import ast
import pathlib

import pytest

import mocap


def test_the_stubs_parse_and_cover_every_public_name():
    stub = pathlib.Path(mocap.__file__).with_name("mocap.pyi")
    if not stub.exists():
        pytest.skip("mocap.pyi is written by the build (target mocap_python_stubs)")
    tree = ast.parse(stub.read_text())
    named = {node.name for node in tree.body if isinstance(node, (ast.ClassDef, ast.FunctionDef))}
    named |= {node.target.id for node in tree.body if isinstance(node, ast.AnnAssign)}
    public = {name for name in vars(mocap) if not name.startswith("_")}
    assert public <= named, "not in the stubs: %s" % sorted(public - named)
    take = next(node for node in tree.body if isinstance(node, ast.ClassDef) and node.name == "Take")
    members = {getattr(n, "name", None) or getattr(getattr(n, "target", None), "id", None) for n in take.body}
    assert {"positions", "raw_positions", "valid", "states", "gaps", "write"} <= members


def test_every_public_function_and_class_says_what_it_does():
    undocumented = []
    for name, value in vars(mocap).items():
        if name.startswith("_") or not callable(value):
            continue
        prose = [line for line in (value.__doc__ or "").splitlines()
                 if line.strip() and not line.startswith(name + "(") and not line.startswith("Overloaded")]
        if not prose:
            undocumented.append(name)
    assert undocumented == [], "no docstring beyond the signature: %s" % undocumented

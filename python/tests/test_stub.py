"""The type stub (python/whirl/__init__.pyi) names what the package has: every public name of
whirl.__all__ and every public method and property of Model, LinearModel and the tables, so editors
complete what exists (and a new function without its stub fails here)."""
import ast
import inspect
import pathlib

import whirl

STUB = pathlib.Path(whirl.__file__).with_name("__init__.pyi")


def stub_names():
    tree = ast.parse(STUB.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            top.add(node.name)
        if isinstance(node, ast.ClassDef):
            members[node.name] = {n.name if isinstance(n, ast.FunctionDef) else n.target.id
                                  for n in node.body if isinstance(n, (ast.FunctionDef, ast.AnnAssign))}
    return top, members


def public(cls):
    own = set()
    for klass in cls.__mro__:
        if klass.__module__.startswith("whirl"):
            own |= {n for n in vars(klass) if not n.startswith("_")}
    return own


def test_every_public_name_has_a_stub():
    top, members = stub_names()
    assert set(whirl.__all__) - {"lin"} <= top
    for cls in (whirl.Model, whirl.LinearModel, whirl.ExportedModel, whirl.StateSpace, whirl.CampbellTable,
                whirl.BodeTable):
        inherited = set()
        for base in inspect.getmro(cls):
            inherited |= members.get(base.__name__, set())
        assert public(cls) <= inherited, (cls.__name__, public(cls) - inherited)

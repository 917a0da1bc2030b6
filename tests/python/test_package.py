"""The package as an editor and help() see it: every public name documented, and the type stubs
(trailray/__init__.pyi) declaring every public name and attribute the module has."""

import ast
import inspect
import pathlib

import trailray

STUBS = pathlib.Path(trailray.__file__).with_name("__init__.pyi")


def stub_names():
    tree = ast.parse(STUBS.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            top.add(node.name)
        if isinstance(node, ast.ClassDef):
            members[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)} | {
                n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
    return top, members


def test_the_stubs_are_shipped_with_py_typed():
    assert STUBS.is_file() and STUBS.with_name("py.typed").is_file()


def test_every_public_name_is_documented_and_in_the_stubs():
    top, members = stub_names()
    for name in trailray.__all__:
        thing = getattr(trailray, name)
        assert inspect.getdoc(thing), f"{name} has no docstring"
        assert name in top, f"{name} missing from {STUBS.name}"
    for cls in (trailray.File, trailray.Track, trailray.Segment, trailray.Task, trailray.Airspaces):
        public = {n for n in dir(cls) if not n.startswith("_")}
        assert public <= members[cls.__name__], f"{cls.__name__}: {sorted(public - members[cls.__name__])} not in stubs"


def test_nothing_but_the_api_is_exported():
    leaked = {n for n in dir(trailray) if not n.startswith("_")} - set(trailray.__all__)
    assert leaked <= {"annotations", "dask"}, sorted(leaked)  # trailray.dask: a submodule, once imported

"""Unit tests of the mujoco stub generator's rules, on small drafts (no tools run)."""

from __future__ import annotations

import ast

import pytest

from codegen.mujoco_stubs import facts, passes, spelling
from codegen.mujoco_stubs.build import incomplete
from codegen.mujoco_stubs.imports import ensure_imports


def run(source: str, *steps: passes.Pass, module: str = "mujoco._x") -> str:
    tree = ast.parse(source)
    for step in steps:
        step(tree, module)
    return ast.unparse(tree)


def test_cxx_spellings_map_to_python_classes() -> None:
    draft = ("def body(self) -> mujoco::python::MjModelBodyViews: ...\n"
             "def bind(spec: mjsGeom_) -> mujoco::python::_impl::MjWrapper<mjStatistic_>: ...\n"
             "def f(vfs: mujoco::python::MjVfs = None) -> None: ...\n"
             "class V:\n    global: int\n    global_: int\n")
    text = spelling.python_spelling(draft)
    assert "-> mujoco._structs._MjModelBodyViews:" in text
    assert "spec: mujoco._specs.MjsGeom" in text
    assert "-> mujoco._structs.MjStatistic:" in text
    assert "vfs: mujoco._specs.MjVfs" in text
    assert "    global: int" not in text and "    global_: int" in text
    ast.parse(text)
    assert spelling.cxx_left("mjsFoo_ | None") == "mjsFoo_"
    assert spelling.cxx_left("mujoco._specs.MjsFoo") is None


def test_a_default_before_a_required_parameter_is_dropped() -> None:
    line = "    def f(a: bool, b: X = None, c: Y, d: int = 1) -> None:"
    assert spelling.python_spelling(line) == "    def f(a: bool, b: X, c: Y, d: int = 1) -> None:"


def test_inputs_take_sequences_outputs_keep_the_dtype() -> None:
    source = ('def f(out: typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]", '
              '"flags.writeable"], v: typing.Annotated[numpy.typing.NDArray[numpy.float64], '
              '"[3, 1]"], mat: typing.Annotated[numpy.typing.NDArray[numpy.int32], "[m, n]"], '
              'n: typing.SupportsInt | typing.SupportsIndex) -> '
              'typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]: ...')
    text = run(source, passes.annotated_arrays, passes.integers)
    assert "out: numpy.typing.NDArray[numpy.float64]," in text
    assert "v: numpy.typing.NDArray[typing.Any] | collections.abc.Sequence[float]," in text
    assert ("mat: numpy.typing.NDArray[typing.Any] | "
            "collections.abc.Sequence[collections.abc.Sequence[int]]") in text
    assert "n: typing.SupportsIndex)" in text
    assert text.endswith("-> numpy.typing.NDArray[numpy.float64]:\n    ...")


def test_array_setters_take_array_likes_and_none_defaults_become_optional() -> None:
    source = ("class S:\n"
              "    @property\n    def pos(self) -> numpy.typing.NDArray[numpy.float64]: ...\n"
              "    @pos.setter\n    def pos(self, arg1: typing.Any) -> None: ...\n"
              "    def add(self, default: D = None) -> None: ...\n")
    text = run(source, passes.setters, passes.none_defaults)
    assert "def pos(self, value: numpy.typing.ArrayLike) -> None" in text
    assert "default: D | None=None" in text


def test_facts_apply_and_stale_facts_are_reported(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(facts, "RETURNS", {"mujoco.x:f": "int", "mujoco.x:gone": "int"})
    monkeypatch.setattr(facts, "PARAMS", {"mujoco.x:f(a)": "str"})
    monkeypatch.setattr(facts, "ATTRIBUTES", {})
    monkeypatch.setattr(facts, "REPLACE", {"mujoco.x:noise": ""})
    facts.reset()
    tree = ast.parse("def f(a): ...\nnoise: Incomplete\n")
    facts.apply(tree, "mujoco.x")
    assert ast.unparse(tree) == "def f(a: str) -> int:\n    ..."
    assert facts.unused() == ["facts.py: 'mujoco.x:gone' matches no definition"]


def test_untyped_definitions_are_reported() -> None:
    tree = ast.parse("class C:\n    def m(self, x): ...\n    y: Incomplete\n"
                     "def g(v: int) -> mjsBody_: ...\n")
    assert sorted(incomplete(tree, "mujoco.x")) == [
        "mujoco.x: C++ name 'mjsBody_' (add a rule to spelling.py)",
        "mujoco.x: attribute y",
        "mujoco.x: parameter 'x' of m()",
        "mujoco.x: return of m()",
    ]


def test_imports_are_added_and_own_names_unqualified() -> None:
    tree = ast.parse("import typing\ndef f(m: mujoco._structs.MjModel) -> "
                     "numpy.typing.NDArray[typing.Any]: ...\n"
                     "def g(x: mujoco._x.C) -> None: ...\n")
    ensure_imports(tree, "mujoco._x")
    assert ast.unparse(tree).splitlines()[:3] == [
        "import typing", "import mujoco._structs", "import numpy.typing"]
    assert "def g(x: C) -> None" in ast.unparse(tree)


def test_statements_and_classes_are_those_ast_walk_finds_in_its_order() -> None:
    """``syntax.statements`` skips expressions (for speed): the same statements, classes
    nested in every kind of body included, in the same order."""
    from codegen.mujoco_stubs.syntax import classes, statements

    tree = ast.parse(
        "class A:\n    class B:\n        x: int\n    def f(self) -> None:\n"
        "        class C: ...\n"
        "if sys.version_info >= (3, 12):\n    class D: ...\nelse:\n    class E: ...\n"
        "try:\n    class F: ...\nexcept ImportError:\n    class G:\n        y: 'A'\n"
        "finally:\n    z: int = 1\n"
        "for _ in []:\n    class H: ...\nwhile False:\n    class I: ...\n"
        "with open('x'):\n    class J: ...\n"
        "match 1:\n    case 1:\n        class K: ...\n"
        "w: list[int] = [i for i in (lambda: [1])()]\n")
    walked = [node for node in ast.walk(tree) if isinstance(node, ast.stmt)]
    assert list(statements(tree)) == walked
    assert [c.name for c in classes(tree)] == [
        node.name for node in ast.walk(tree) if isinstance(node, ast.ClassDef)]
    assert len(list(classes(tree))) == 11

"""The runtime reads top-down: its modules import each other without cycles, none imports
inside a function to dodge one (the heavy ``mujoco`` aside), tag facts come from the
generated tables, and the generator knows the runtime's public names."""

from __future__ import annotations

import ast
from pathlib import Path

import typed_mjcf as mjcf
from codegen import naming

SRC = Path(mjcf.__file__).resolve().parent
PACKAGE = "typed_mjcf"
# Imports a function may make: optional heavy dependencies.
LAZY_ALLOWED = frozenset({"mujoco"})


def _modules() -> dict[str, Path]:
    return {path.stem: path for path in sorted(SRC.glob("*.py")) if path.stem != "__init__"}


def _is_type_checking(node: ast.If) -> bool:
    return isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING"


def _run_time_imports(tree: ast.Module) -> set[str]:
    """The typed_mjcf modules a module imports when it runs (not for type checkers)."""
    found: set[str] = set()

    def visit(statements: list[ast.stmt]) -> None:
        for node in statements:
            if isinstance(node, ast.If) and _is_type_checking(node):
                visit(node.orelse)
                continue
            if isinstance(node, ast.ImportFrom) and node.module:
                if node.module == PACKAGE:
                    found.update(alias.name for alias in node.names)
                elif node.module.startswith(PACKAGE + "."):
                    found.add(node.module.split(".")[1])
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name.startswith(PACKAGE + "."):
                        found.add(alias.name.split(".")[1])
            elif isinstance(node, ast.If | ast.Try | ast.With):
                visit([*node.body, *getattr(node, "orelse", []),
                       *getattr(node, "finalbody", [])])

    visit(tree.body)
    return found


def test_the_runtime_modules_import_each_other_without_cycles() -> None:
    modules = _modules()
    graph = {name: _run_time_imports(ast.parse(path.read_text(encoding="utf-8"))) & set(modules)
             for name, path in modules.items()}
    order: list[str] = []
    state: dict[str, str] = {}

    def visit(name: str, chain: list[str]) -> None:
        if state.get(name) == "done":
            return
        assert state.get(name) != "open", "import cycle: " + " -> ".join([*chain, name])
        state[name] = "open"
        for dependency in sorted(graph[name]):
            visit(dependency, [*chain, name])
        state[name] = "done"
        order.append(name)

    for name in graph:
        visit(name, [])
    assert order.index("_tree") < order.index("_export") < order.index("_base")


def test_no_import_hides_in_a_function() -> None:
    hidden: list[str] = []
    for name, path in _modules().items():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for function in ast.walk(tree):
            if not isinstance(function, ast.FunctionDef | ast.AsyncFunctionDef):
                continue
            for node in ast.walk(function):
                if isinstance(node, ast.Import | ast.ImportFrom):
                    modules = ([a.name for a in node.names] if isinstance(node, ast.Import)
                               else [node.module or ""])
                    hidden += [f"{name}.{function.name}: {m}" for m in modules
                               if m.split(".")[0] not in LAZY_ALLOWED]
    assert not hidden, hidden


def test_no_private_usage_is_silenced_outside_the_core() -> None:
    """Features use the core's internal API; only the core (``_tree``) reads element slots.
    The one ignore left names lxml's own element class (``types.py``)."""
    silenced = [f"{path.name}:{i}" for path in sorted(SRC.glob("*.py"))
                for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
                if "reportPrivateUsage" in line]
    assert [s.split(":")[0] for s in silenced] == ["_tree.py", "types.py"], silenced


# MJCF tag and attribute names the runtime might spell itself; they must come from the
# generated tables (schema/facts.toml's [language]) instead.
_TAG_NAMES = frozenset({
    "body", "geom", "joint", "site", "worldbody", "default", "actuator", "sensor", "frame",
    "replicate", "attach", "keyframe", "mesh", "texture", "freejoint", "inertial", "class",
    "childclass", "model", "mocap", "objtype", "objname", "world", "main", "type", "free",
})


def _string_constants(tree: ast.Module) -> list[ast.Constant]:
    """String constants in code: not docstrings, not ``__slots__`` entries."""
    skipped: set[int] = set()
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if isinstance(body, list) and body and isinstance(body[0], ast.Expr) and isinstance(
                body[0].value, ast.Constant):
            skipped.add(id(body[0].value))
        if isinstance(node, ast.Assign) and any(
                isinstance(t, ast.Name) and t.id == "__slots__" for t in node.targets):
            skipped.update(id(c) for c in ast.walk(node.value))
    return [node for node in ast.walk(tree) if isinstance(node, ast.Constant)
            and isinstance(node.value, str) and id(node) not in skipped]


# Strings spelled like a tag that are not one: (module, string) -> what it is.
_NOT_TAGS = {
    ("cli/to_python.py", "model"): "the root's variable in the code written, and the "
                                   "command's argument",
}


def test_tag_facts_come_from_the_generated_tables() -> None:
    """In the runtime and the command line alike."""
    paths = sorted(SRC.rglob("*.py"))
    found = [f"{path.relative_to(SRC)}:{node.lineno}: {node.value!r}" for path in paths
             for node in _string_constants(ast.parse(path.read_text(encoding="utf-8")))
             if node.value in _TAG_NAMES
             and (path.relative_to(SRC).as_posix(), node.value) not in _NOT_TAGS]
    assert not found, "\n".join(found)


def test_the_generator_knows_the_runtime_public_names() -> None:
    """A child or attribute named like a runtime member would shadow it: the generator
    renames children (``attach_``) and refuses attributes by this list."""
    public = {name for cls in (mjcf.Element, mjcf.ModelRoot, mjcf.Body)
              for name in dir(cls) if not name.startswith("_")}
    runtime = {name for name in public
               if not any(name == a.py_name or name == "dclass"
                          for cls in (mjcf.Body, mjcf.RootElement)
                          for a in cls.spec.attributes.values())
               and name not in {c.py_name for cls in (mjcf.Body, mjcf.RootElement)
                                for c in cls.spec.children.values()}
               and not name.startswith("add_")}
    assert runtime <= naming.RESERVED, sorted(runtime - naming.RESERVED)

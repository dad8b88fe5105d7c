"""The runtime reads top-down: its modules (the command line and the generated package
included) import each other without cycles, imports for type checkers point down the floors
too and close no circle, none imports inside a function to dodge a cycle (the heavy ``mujoco``
aside), tag facts come from the generated tables, and the generator knows the runtime's
public names."""

from __future__ import annotations

import ast
import os
import re
from pathlib import Path

import typed_mjcf as mjcf
from codegen import naming
from typed_mjcf import tooling

SRC = Path(mjcf.__file__).resolve().parent
PACKAGE = "typed_mjcf"
# Imports a function may make: optional heavy dependencies.
LAZY_ALLOWED = frozenset({"mujoco"})
# Other imports made in a function, each with why: (module.function, module imported).
LAZY_EXCEPTIONS = {
    ("__init__.__getattr__", "importlib"): "typed_mjcf.physics (and mujoco) load on first use",
    ("_dmcompat.mjcf.__getattr__", "typed_mjcf"): "dm_control.mjcf's other names are the "
                                                   "package's, which imports _dmcompat",
}


def _modules() -> dict[str, Path]:
    """Every module of the package by dotted name below it (``_tree``, ``cli.fmt``; a
    subpackage's ``__init__`` by the subpackage's name), the command line's included; the
    package's own ``__init__`` (the public API, above everything) is ``__init__``."""
    found: dict[str, Path] = {}
    for folder, _, files in sorted(os.walk(SRC, followlinks=True)):  # _generated: a link
        for file in sorted(f for f in files if f.endswith(".py")):
            path = Path(folder) / file
            parts = path.relative_to(SRC).with_suffix("").parts
            if parts[-1] == "__init__" and len(parts) > 1:
                parts = parts[:-1]
            found[".".join(parts)] = path
    return found


MODULES = _modules()


def _is_type_checking(node: ast.If) -> bool:
    return isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING"


def _targets(node: ast.Import | ast.ImportFrom) -> set[str]:
    """The package's modules an import statement loads."""
    if isinstance(node, ast.Import):
        return {_module_of(alias.name.split(".")[1:]) for alias in node.names
                if alias.name.startswith(PACKAGE + ".")}
    assert node.level == 0, "the package imports absolutely"
    if node.module != PACKAGE and not (node.module or "").startswith(PACKAGE + "."):
        return set()
    base = (node.module or "").split(".")[1:]
    return {_module_of([*base, alias.name]) for alias in node.names}


def _module_of(parts: list[str]) -> str:
    """The module ``parts`` names, or the module holding the name (``__init__`` for one of
    the package's own names)."""
    while parts and ".".join(parts) not in MODULES:
        parts = parts[:-1]
    return ".".join(parts) if parts else "__init__"


def _imports(tree: ast.Module) -> tuple[set[str], set[str]]:
    """The modules a module imports when it runs, and those it imports only for type
    checkers (``if TYPE_CHECKING:``)."""
    run_time: set[str] = set()
    typing_only: set[str] = set()

    def visit(statements: list[ast.stmt], found: set[str]) -> None:
        for node in statements:
            if isinstance(node, ast.If) and _is_type_checking(node):
                visit(node.body, typing_only)
                visit(node.orelse, found)
            elif isinstance(node, ast.Import | ast.ImportFrom):
                found.update(_targets(node))
            elif isinstance(node, ast.If | ast.Try | ast.With):
                visit([*node.body, *getattr(node, "orelse", []),
                       *getattr(node, "finalbody", [])], found)
                for handler in getattr(node, "handlers", []):
                    visit(handler.body, found)

    visit(tree.body, run_time)
    return run_time, typing_only


def _graphs() -> tuple[dict[str, set[str]], dict[str, set[str]]]:
    run_time: dict[str, set[str]] = {}
    typing_only: dict[str, set[str]] = {}
    for name, path in MODULES.items():
        found, types = _imports(ast.parse(path.read_text(encoding="utf-8")))
        run_time[name] = found - {name}
        typing_only[name] = types - {name}
    return run_time, typing_only


def _reaches(graph: dict[str, set[str]], start: str, goal: str) -> bool:
    seen: set[str] = set()
    stack = [start]
    while stack:
        current = stack.pop()
        if current == goal:
            return True
        if current not in seen:
            seen.add(current)
            stack.extend(graph.get(current, ()))
    return False


def test_the_modules_import_each_other_without_cycles() -> None:
    """The runtime, the generated package and the command line alike."""
    graph, _ = _graphs()
    assert {"_core.tree", "cli", "cli.fmt", "cli._values", "_generated.elements"} <= set(graph)
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
    assert order.index("_core.tree") < order.index("_text.export") < order.index("_base")


# The floors, bottom up: a module imports (at run time or for type checkers) only modules of
# its own floor or below. A folder is one floor; the package's root modules and the
# generated tables sit where what they hold belongs.
FLOORS: dict[str, int] = {
    "_core": 0, "assets": 0, "types": 0, "_generated": 0,  # the value types, the version
    "_build": 0,  # which build runs (pure or compiled by mypyc), and mypyc's markers
    "_releases": 1, "_generated.releases": 1, "_generated.release_facts": 1,
    "_text": 2,
    "_model": 3,
    "_sim": 4,
    # the API: the element facade the generated classes subclass, and the public modules
    "_base": 5, "_generated.elements": 5, "_generated.bindings": 5, "errors": 5, "io": 5,
    "physics": 5, "parametric": 5, "tooling": 5,  # tooling: the internal API of tools (the command line)
    "_dmcompat": 6,  # the compat room: dm_control.mjcf's modules over the API
    "variation": 6, "warp": 6,  # many worlds from one model: features over the API
    "__init__": 7,  # the package: everything users import
    "cli": 8, "__main__": 8,  # the command line: a tool over the package
}
# Imports that point up the floors, each with why (and the issue that removes it).
UPWARD = {
}


def floor(name: str) -> int:
    """The floor of module ``name``: its own entry, else its folder's."""
    parts = name.split(".")
    while parts:
        found = FLOORS.get(".".join(parts))
        if found is not None:
            return found
        parts = parts[:-1]
    raise AssertionError(f"{name} is on no floor: add it (or its folder) to FLOORS")


def test_the_floors_are_respected_or_say_why() -> None:
    """Run-time and type-only imports alike point down (or sideways, within a floor)."""
    graph, typing_only = _graphs()
    upward = {(name, target) for name in graph for target in graph[name] | typing_only[name]
              if floor(target) > floor(name)}
    assert upward == set(UPWARD), sorted(upward ^ set(UPWARD))


def test_the_core_knows_nothing_of_releases() -> None:
    """Releases gate and retype the core's tables from outside, through its hooks."""
    graph, typing_only = _graphs()
    core = [name for name in graph if floor(name) == 0]
    found = [(name, target) for name in core for target in graph[name] | typing_only[name]
             if target.startswith(("_releases", "_generated.release"))]
    assert not found, found


def test_only_the_command_line_imports_the_command_line() -> None:
    """``cli/`` is the top floor (tools): the library never imports it."""
    graph, typing_only = _graphs()
    upward = [f"{name} -> {target}" for name in graph if not _in_cli(name)
              for target in graph[name] | typing_only[name] if _in_cli(target)]
    assert not upward, upward


def _in_cli(name: str) -> bool:
    return name in ("cli", "__main__") or name.startswith("cli.")


def _is_private(name: str) -> bool:
    return any(part.startswith("_") and part != "__init__" for part in name.split("."))


def test_the_command_line_imports_only_public_modules_and_the_tooling_api() -> None:
    """``cli/`` reaches the runtime through ``typed_mjcf``, its public modules and
    ``typed_mjcf.tooling`` (stable for tools), never a private module of the runtime."""
    graph, typing_only = _graphs()
    private = sorted(f"{name} -> {target}" for name in graph if _in_cli(name)
                     for target in graph[name] | typing_only[name]
                     if _is_private(target) and not _in_cli(target))
    assert not private, private


def test_the_tooling_api_exports_what_the_command_line_imports() -> None:
    """No more (a name no tool uses is not kept stable for nothing), no less."""
    imported: set[str] = set()
    for name, path in MODULES.items():
        if _in_cli(name):
            imported |= {alias.name for node in ast.walk(ast.parse(path.read_text("utf-8")))
                         if isinstance(node, ast.ImportFrom) and node.module == "typed_mjcf.tooling"
                         for alias in node.names}
            imported |= set(re.findall(r"\btooling\.(\w+)", path.read_text("utf-8")))
    assert imported == set(tooling.__all__), sorted(imported ^ set(tooling.__all__))


def test_type_only_imports_close_no_circle() -> None:
    """An import for type checkers only never names a module that imports the importer
    (even through others) when the code runs: a lower module types what an upper one
    gives it by a protocol of its own (``_core.grammar.RowClass``), a type parameter
    (``_base.ModelRoot``'s camera and key) or the generated stubs (``attach()``'s frame)."""
    graph, typing_only = _graphs()
    circles = sorted((name, target) for name, targets in typing_only.items()
                     for target in targets if _reaches(graph, target, name))
    assert not circles, circles


def test_no_import_hides_in_a_function() -> None:
    hidden: list[str] = []
    for name, path in MODULES.items():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for function in ast.walk(tree):
            if not isinstance(function, ast.FunctionDef | ast.AsyncFunctionDef):
                continue
            for node in ast.walk(function):
                if isinstance(node, ast.Import | ast.ImportFrom):
                    modules = ([a.name for a in node.names] if isinstance(node, ast.Import)
                               else [node.module or ""])
                    hidden += [f"{name}.{function.name}: {m}" for m in modules
                               if m.split(".")[0] not in LAZY_ALLOWED
                               and (f"{name}.{function.name}", m) not in LAZY_EXCEPTIONS]
    assert not hidden, hidden


def test_no_private_usage_is_silenced_outside_the_core() -> None:
    """Features use the core's internal API; only the core (``_core/tree.py``) reads element
    slots. The one ignore left names lxml's own element class (``types.py``)."""
    silenced = [f"{path.relative_to(SRC).as_posix()}:{i}" for path in sorted(SRC.rglob("*.py"))
                for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
                if "reportPrivateUsage" in line]
    assert [s.split(":")[0] for s in silenced] == ["_core/tree.py", "types.py"], silenced


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
    """In the runtime and the command line alike; the generated tables themselves are left
    out by name (in the repository `_generated` is a link, which rglob does not follow; an
    installed wheel holds it as a real folder)."""
    paths = sorted(path for path in SRC.rglob("*.py")
                   if path.relative_to(SRC).parts[0] != "_generated")
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

"""Add the ``import`` statements that the rewritten annotations need.

Passes and facts write fully qualified names (``numpy.typing.ArrayLike``,
``mujoco._structs.MjModel``) instead of tracking each module's imports; this pass then imports
every module such a name starts with, once, after the module's own imports.
"""

from __future__ import annotations

import ast

from codegen.mujoco_stubs.syntax import dotted

# Top-level packages whose dotted names the passes and facts write.
_ROOTS = ("collections", "contextlib", "ctypes", "mujoco", "numpy", "types", "typing")


def _bound_names(tree: ast.Module) -> tuple[set[str], set[str]]:
    """(names bound other than by ``import x``, modules imported by ``import x.y``)."""
    other: set[str] = set()
    modules: set[str] = set()
    for stmt in tree.body:
        if isinstance(stmt, ast.Import):
            for alias in stmt.names:
                if alias.asname is not None and alias.asname != alias.name:
                    other.add(alias.asname)
                else:
                    modules.add(alias.name)
        elif isinstance(stmt, ast.ImportFrom):
            other.update(a.asname or a.name for a in stmt.names)
        elif isinstance(stmt, ast.ClassDef | ast.FunctionDef):
            other.add(stmt.name)
    return other, modules


class _Local(ast.NodeTransformer):
    """``mujoco._structs.MjModel`` inside ``mujoco._structs`` -> ``MjModel``."""

    def __init__(self, module: str) -> None:
        self.prefix = module + "."

    def visit_Attribute(self, node: ast.Attribute) -> ast.AST:
        name = dotted(node)
        if name is not None and name.startswith(self.prefix) \
                and "." not in name.removeprefix(self.prefix):
            return ast.Name(name.removeprefix(self.prefix))
        return self.generic_visit(node)


def ensure_imports(tree: ast.Module, module: str) -> None:
    """Insert ``import a.b`` for every ``a.b.Name`` in ``tree`` that nothing imports yet.

    Names of the module itself lose their prefix: pyright does not resolve
    ``mujoco._structs.X`` inside ``mujoco/_structs.pyi`` without a self-import.
    """
    _Local(module).visit(tree)
    other, modules = _bound_names(tree)
    needed: set[str] = set()
    inner = {id(n.value) for n in ast.walk(tree) if isinstance(n, ast.Attribute)}
    for node in ast.walk(tree):
        if not isinstance(node, ast.Attribute) or id(node) in inner:
            continue  # only whole chains: mujoco._structs.MjModel, not mujoco._structs
        name = dotted(node)
        if name is None:
            continue
        parts = name.split(".")
        if parts[0] not in _ROOTS or parts[0] in other:
            continue
        target = ".".join(parts[:-1])
        if target and target != module and target not in modules:
            needed.add(target)
    # an import of "mujoco._structs" inside "numpy.typing.NDArray"-style chains: keep only
    # real module paths (the class part of mujoco._structs.MjModel.x is not a module)
    needed = {n for n in needed if not any(p[:1].isupper() for p in n.split(".")[1:])}
    if not needed:
        return
    at = 0
    for i, stmt in enumerate(tree.body):
        if isinstance(stmt, ast.Import | ast.ImportFrom):
            at = i + 1
        elif i > 0 and not isinstance(stmt, ast.Expr):
            break
    new = [ast.Import(names=[ast.alias(name)]) for name in sorted(needed)]
    tree.body[at:at] = new

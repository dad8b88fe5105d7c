"""Small helpers over ``ast`` annotations shared by the passes: dotted names and unions."""

from __future__ import annotations

import ast
from collections import deque
from collections.abc import Iterator
from typing import cast


def dotted(node: ast.expr) -> str | None:
    """``typing.Any`` for ``Attribute(Name('typing'), 'Any')``; ``None`` for anything else."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        base = dotted(node.value)
        return None if base is None else f"{base}.{node.attr}"
    return None


def parse_expr(text: str) -> ast.expr:
    """An annotation expression from source text."""
    return ast.parse(text, mode="eval").body


def members(node: ast.expr) -> list[ast.expr]:
    """The members of a ``A | B | C`` union (one member for anything else)."""
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):
        return members(node.left) + members(node.right)
    return [node]


def union(parts: list[ast.expr]) -> ast.expr:
    """``A | B | C`` from its members (at least one)."""
    result = parts[0]
    for part in parts[1:]:
        result = ast.BinOp(left=result, op=ast.BitOr(), right=part)
    return result


def is_none(node: ast.expr) -> bool:
    return isinstance(node, ast.Constant) and node.value is None


def decorators(node: ast.FunctionDef) -> list[str]:
    """Decorator names as written: ``property``, ``typing.overload``, ``x.setter``."""
    return [name for d in node.decorator_list if (name := dotted(d)) is not None]


def is_setter(node: ast.FunctionDef) -> bool:
    return any(d.endswith(".setter") for d in decorators(node))


def is_getter(node: ast.FunctionDef) -> bool:
    return "property" in decorators(node)


def docstring_of(body: list[ast.stmt]) -> str | None:
    if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
        value = body[0].value.value
        return value if isinstance(value, str) else None
    return None


def definitions(tree: ast.Module, module: str) -> Iterator[tuple[str, ast.stmt, list[ast.stmt]]]:
    """``(module:Qual.name, statement, the body holding it)`` for every def, class, attribute.

    Classes are visited before their members, so a pass may rewrite a class body first.
    """
    def walk(body: list[ast.stmt], prefix: str) -> Iterator[tuple[str, ast.stmt, list[ast.stmt]]]:
        for stmt in list(body):
            if isinstance(stmt, ast.ClassDef):
                yield f"{prefix}{stmt.name}", stmt, body
                yield from walk(stmt.body, f"{prefix}{stmt.name}.")
            elif isinstance(stmt, ast.FunctionDef):
                yield f"{prefix}{stmt.name}", stmt, body
            elif isinstance(stmt, ast.AnnAssign) and isinstance(stmt.target, ast.Name):
                yield f"{prefix}{stmt.target.id}", stmt, body
            elif isinstance(stmt, ast.Assign) and len(stmt.targets) == 1 \
                    and isinstance(stmt.targets[0], ast.Name):
                yield f"{prefix}{stmt.targets[0].id}", stmt, body
    yield from walk(tree.body, f"{module}:")


def functions(tree: ast.Module) -> Iterator[tuple[ast.FunctionDef, bool]]:
    """Every function in ``tree`` with whether it is a method (defined in a class body)."""
    def walk(body: list[ast.stmt], in_class: bool) -> Iterator[tuple[ast.FunctionDef, bool]]:
        for stmt in body:
            if isinstance(stmt, ast.ClassDef):
                yield from walk(stmt.body, True)
            elif isinstance(stmt, ast.FunctionDef):
                yield stmt, in_class
    yield from walk(tree.body, False)


# What holds statements: an expression never does, so a walk over these alone meets every
# statement ``ast.walk`` meets, in its order, without visiting the stubs' many annotations
# (most of the nodes: ast.walk made the stubs' build spend a quarter of its time here).
_HOLDERS = (ast.stmt, ast.excepthandler, ast.match_case)


def statements(tree: ast.Module) -> Iterator[ast.stmt]:
    """Every statement in ``tree``, nested ones too, in ``ast.walk``'s order (breadth
    first; a statement's children are queued before it is yielded, as there)."""
    todo: deque[ast.AST] = deque([tree])
    while todo:
        node = todo.popleft()
        for _, value in ast.iter_fields(node):
            if isinstance(value, list):
                todo.extend(item for item in cast("list[object]", value)
                            if isinstance(item, _HOLDERS))
        if isinstance(node, ast.stmt):
            yield node


def classes(tree: ast.Module) -> Iterator[ast.ClassDef]:
    """Every class in ``tree``, nested ones too."""
    for node in statements(tree):
        if isinstance(node, ast.ClassDef):
            yield node

"""``[language]`` of ``schema/facts.toml``, read, stored and rendered from one declaration.

The declaration is :class:`typed_mjcf._core.language.GrammarFacts`: each field is one key, its
type says what the key holds (``str``, ``int``, ``bool``, ``Literal[...]``, ``frozenset[str]``,
``tuple[str, ...]``, ``Mapping[str, T]``, another frozen dataclass of that module as a
sub-table, ``T | None`` for a key that may be left out). Nothing here names a fact: a new one
is a field there and an entry in facts.toml. The module is loaded by its path (it imports
nothing from ``typed_mjcf``), so a generated package made stale by a new field cannot stop
the generator from importing it.
"""

from __future__ import annotations

import dataclasses
import types
import typing
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from codegen.errors import FactsError
from codegen.runtime import core_module

if TYPE_CHECKING:
    from typed_mjcf._core import language as declaration
else:  # the module alone, without the package's __init__ (see codegen/runtime.py)
    declaration = core_module("_core/language")

GrammarFacts = declaration.GrammarFacts
_D = TypeVar("_D")


def read_table(cls: type[_D], value: object, where: str) -> _D:
    """``value`` (a TOML or JSON table) as a ``cls``; a mistake raises FactsError naming the
    key and what was expected. Every field is required except those typed ``X | None`` and
    those the generator sets (``FROM_GRAMMAR``)."""
    table = _table(value, where)
    fields = _fields(cls)
    unknown = sorted(set(table) - set(fields))
    if unknown:
        raise FactsError(f"{where}: unknown key {unknown[0]!r} (known keys: "
                         f"{', '.join(fields)})")
    hints = typing.get_type_hints(cls)
    values: dict[str, object] = {}
    for name in fields:
        hint = hints[name]
        if name in table:
            values[name] = _value(hint, table[name], f"{where} {name}")
        elif not _optional(hint):
            raise FactsError(f"{where}: missing key {name!r} ({_describe(hint)})")
    return cls(**cast(dict[str, Any], values))


def to_plain(value: object) -> object:
    """``value`` as JSON-ready data (sets sorted; generator-set fields left out)."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {name: to_plain(getattr(value, name)) for name in _fields(type(value))
                if getattr(value, name) is not None}
    if isinstance(value, frozenset):
        return sorted(cast(frozenset[str], value))
    if isinstance(value, tuple):
        return [to_plain(v) for v in cast(tuple[object, ...], value)]
    if isinstance(value, Mapping):
        items = cast(Mapping[str, object], value)
        return {k: to_plain(items[k]) for k in sorted(items)}
    return value


def source(value: object) -> str:
    """``value`` as a Python expression (the generated tables' ``GrammarFacts(...)``)."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        args = ", ".join(f"{f.name}={source(getattr(value, f.name))}"
                         for f in dataclasses.fields(value))
        return f"{type(value).__name__}({args})"
    if isinstance(value, frozenset):
        return f"frozenset({sorted(cast(frozenset[str], value))!r})"
    if isinstance(value, Mapping):
        items = cast(Mapping[str, object], value)
        return "{" + ", ".join(f"{k!r}: {source(items[k])}" for k in sorted(items)) + "}"
    if isinstance(value, tuple):
        return repr(tuple(cast(tuple[object, ...], value)))
    return repr(value)


def classes() -> list[str]:
    """The declaration's classes a rendered ``GrammarFacts(...)`` may name."""
    return sorted(name for name, obj in vars(declaration).items()
                  if isinstance(obj, type) and dataclasses.is_dataclass(obj)
                  and obj.__module__ == declaration.__name__)


# ------------------------------------------------------------------------------ types


def _fields(cls: type) -> list[str]:
    return [f.name for f in dataclasses.fields(cls)
            if f.metadata.get("source") != declaration.FROM_GRAMMAR["source"]]


def _optional(hint: object) -> bool:
    return isinstance(hint, types.UnionType) and type(None) in typing.get_args(hint)


def _describe(hint: object) -> str:
    """What a key of this type holds, in the words of a facts.toml author."""
    origin, args = typing.get_origin(hint), typing.get_args(hint)
    if hint is str:
        return "a string"
    if hint is bool:
        return "true or false"
    if hint is int:
        return "an integer"
    if origin is typing.Literal:
        return "one of " + ", ".join(repr(a) for a in args)
    if origin in (frozenset, tuple):
        return "a list of strings"
    if origin is Mapping:
        return f"a table of {_describe(args[1]).removeprefix('a ').removeprefix('an ')}s"
    if isinstance(hint, types.UnionType):
        return _describe(next(a for a in args if a is not type(None)))
    if isinstance(hint, type) and dataclasses.is_dataclass(hint):
        return f"a table with keys {', '.join(_fields(hint))}"
    raise TypeError(f"GrammarFacts declares a type the generator cannot read: {hint!r}")


def _value(hint: object, value: object, where: str) -> object:
    origin, args = typing.get_origin(hint), typing.get_args(hint)
    mistake = FactsError(f"{where}: expected {_describe(hint)}, got {value!r}")
    if isinstance(hint, types.UnionType):
        return _value(next(a for a in args if a is not type(None)), value, where)
    if isinstance(hint, type) and dataclasses.is_dataclass(hint):
        return read_table(hint, value, where)
    if origin is Mapping:
        return {k: _value(args[1], v, f"{where} {k}") for k, v in _table(value, where).items()}
    if origin in (frozenset, tuple):
        if not isinstance(value, list) or not all(
                isinstance(v, str) for v in cast(list[object], value)):
            raise mistake
        strings = cast(list[str], value)
        return frozenset(strings) if origin is frozenset else tuple(strings)
    if origin is typing.Literal:
        if value not in args:
            raise mistake
        return value
    if (hint in (str, bool) or (hint is int and not isinstance(value, bool))) and isinstance(
            value, cast(type, hint)):
        return value
    raise mistake


def _table(value: object, where: str) -> dict[str, object]:
    if not isinstance(value, dict):
        raise FactsError(f"{where}: expected a table, got {value!r}")
    return {str(k): v for k, v in cast(dict[object, object], value).items()}

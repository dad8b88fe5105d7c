# Generated from src/typed_mjcf/_core/behaviour.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Where the typed API's choices and dm_control's observable behaviour differ: a table of
named behaviours (:class:`Behaviour`), each flag read where it acts.

Two presets: :meth:`Behaviour.typed` (every flag off, the default) and
:meth:`Behaviour.dm_control` (every flag on), which ``install_as_dm_control_mjcf()`` selects.
A user may select either, or a table of their own (``Behaviour(arrays_in_place=True)``),
with :func:`set_behaviour` or the :func:`behaviour` context manager. The docs' list of
differences (docs/guide/dm-control.md) is :func:`listing` (a test holds them equal).

A new behaviour: a field here (its one-line ``doc``), read where it acts as
``FLAGS.<name>``; what it does that only dm_control does lives in ``_dmcompat/`` (the tree
calls it through ``typed_mjcf._core.tree.COMPAT``); its check in ``tests/dm_control/
test_behaviours.py``.
"""
from __future__ import annotations
import contextlib
from collections.abc import Generator
from dataclasses import dataclass, field
from typing import Final

@dataclass(frozen=True, slots=True)
class Behaviour:
    """Which of dm_control's behaviours are on (each flag's ``doc``: what it does)."""
    arrays_in_place: bool = field(default=False, metadata={"doc":
        "arrays read as writable arrays, edited in place and checked again when written"})
    on_demand_children: bool = field(default=False, metadata={"doc":
        "`body.inertial` (a once-only child of an element holding bodies) is `None` "
        "until added"})
    single_freejoint: bool = field(default=False, metadata={"doc":
        "`body.freejoint` is the one free joint or `None`, not a list"})
    once_only_children_by_tag: bool = field(default=False, metadata={"doc":
        "`get_children(tag)` of a once-only child's tag gives that child itself"})
    eager_children: bool = field(default=False, metadata={"doc":
        "once-only children that are not on demand exist with their parent "
        "(`get_children()` lists them, `add()` of one is refused)"})
    unnamed_identifiers: bool = field(default=False, metadata={"doc":
        "unnamed elements are named `//unnamed_<kind>_<i>` (in `full_identifier`, the XML "
        "and the compiled model)"})
    frame_names_end_in_separator: bool = field(default=False, metadata={"doc":
        "an attachment frame's own named children are named `scope/name/`"})
    unnamed_model_name: bool = field(default=False, metadata={"doc":
        "a model given no name is named `unnamed_model`"})
    hashed_file_names: bool = field(default=False, metadata={"doc":
        "files are named `<stem>-<SHA-1 of contents><ext>`, flat, also in "
        "`to_xml_string()`"})
    named_after_files: bool = field(default=False, metadata={"doc":
        "unnamed meshes, textures, heightfields and skins are named after their file's stem"})
    references_stay_names: bool = field(default=False, metadata={"doc":
        "a reference given by name reads as that name; it links on `resolve_references()` "
        "(which a parse runs)"})
    element_name_keyword: bool = field(default=False, metadata={"doc":
        "`add(element_name=\"geom\", ...)` names the tag by keyword"})
    scalar_copies: bool = field(default=False, metadata={"doc":
        "`physics.bind(element).<field>` of a single value is a numpy scalar (a copy), not "
        "a 0-d view"})
    dm_control_physics_error: bool = field(default=False, metadata={"doc":
        "`mjcf.PhysicsError` is also `dm_control.rl.control.PhysicsError` once that is "
        "imported"})
    compile_error_advice: bool = field(default=False, metadata={"doc":
        "a model `Physics` refuses gets dm_control's debug-mode advice (or findings) in its "
        "error"})
    @classmethod
    def typed(cls) -> Behaviour:
        """The typed API's choices: every flag off (the default)."""
        ...
    @classmethod
    def dm_control(cls) -> Behaviour:
        """dm_control's behaviour: every flag on (``install_as_dm_control_mjcf()``)."""
        ...
FLAGS: Final = Behaviour()

def current_behaviour() -> Behaviour:
    """The behaviour selected now (a copy: it does not follow later changes)."""
    ...

def set_behaviour(selected: Behaviour) -> Behaviour:
    """Select ``selected`` (a preset or a table of your own); return the one it replaces."""
    ...

@contextlib.contextmanager
def behaviour(selected: Behaviour) -> Generator[Behaviour]:
    """Select ``selected`` while the block runs, then the behaviour before it again."""
    ...

def listing() -> list[str]:
    """The flags as the docs list them: ``- `name`: what it does``, one line each."""
    ...

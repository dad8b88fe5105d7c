# Generated from src/typed_mjcf/_sim/ids.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Compiling a model for a physics, and which compiled objects each element became.

A named element is found by the name it is written with (its scope's prefix and its name):
``mj_name2id``. An unnamed one has no name to find it by, and MuJoCo's order of objects is not
the document's (a body's geoms come before its children's, replicates copy, ``<attach>``
reads other files), so the model is written with a marker name on every unnamed element that
can be bound, read into an ``MjSpec``, the markers found there (a ``<replicate>``'s copies
carry the marker with their suffix), set back to no name, and the spec compiled: the objects
keep the ids the compiler gives them, and the model is the one the text without markers
gives (names do not change how MuJoCo compiles).
"""
from __future__ import annotations
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
from typed_mjcf._model.resource_limits import DEFAULT_COMPILE_LIMITS, CompileLimits, check_compile
import mujoco

def kind_of(element: Element) -> str | None:
    """The kind of compiled object ``element`` becomes (``"joint"``, ``"body"`` for the world
    body too), or ``None`` if it becomes none MuJoCo indexes."""
    ...

def bound_kind(namespace: str | None) -> str | None:
    """``namespace`` if its elements become objects MuJoCo indexes (a kind bind knows)."""
    ...

def row_kind(cls: type) -> str | None:
    """The kind of every element of class ``cls``: its row's namespace, if MuJoCo binds it
    (``None`` for the world body's row, which has none: :func:`kind_of` decides it)."""
    ...

@dataclass(frozen=True, slots=True)
class Compiled:
    """A compiled model, and the compiled ids of the elements bound without their own name
    (``id(element) -> (element, ids)``; a replicated element has one id per copy)."""
    model: mujoco.MjModel
    unnamed: Mapping[int, tuple[Element, tuple[int, ...]]]

def compile_for_physics(model: ModelBase,
                        limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> Compiled:
    """Validate and compile ``model`` as ``compile()`` does (within ``limits``), keeping the
    ids of its unnamed elements (and of those the export names, as it names attachment
    frames)."""
    ...

def ids_for_text(model: ModelBase, text: str, files: Mapping[str, bytes],
                 ) -> Mapping[int, tuple[Element, tuple[int, ...]]] | None:
    """The compiled ids of ``model``'s unnamed elements in a physics compiled from ``text``
    (dm_control's ``Physics.from_xml_string(model.to_xml_string(), ...)``), found by compiling
    the same text with markers; ``None`` if ``text`` is not ``model.to_xml_string()``."""
    ...

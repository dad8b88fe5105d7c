# Generated from src/typed_mjcf/_sim/locate.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Which element of our model a MuJoCo error is about.

MuJoCo ends an error with where it happened, on a line of its own (the last such line is
about the text it was given; earlier ones about files that text read):

- ``Element 'geom', line 4``: its XML reader, at a line of the text;
- ``Element name 'arm/l', id 3, line 7``: an object of the model being compiled (a body,
  joint, actuator, ...: MuJoCo does not say which kind), its name (``''`` if unnamed), its
  number among objects of its kind, and the line of the element it was read from;
- ``Element name 'k', id 0`` without a line: an object MuJoCo made itself (the bodies of a
  ``<flexcomp>``, the equality of its ``<edge equality>``) or compiles apart (keyframes).

The line is of the text typed-mjcf wrote, where an attached model's elements are written
inline and composition joins sections, so lines cannot be paired with our elements in
document order. Instead the model is written again with the same lines and a marker name on
every unnamed element that has a name attribute: the element at MuJoCo's line is then known
by its name, or by its position under the nearest element known by name. A line is trusted
only when the element there agrees with the name MuJoCo gives; otherwise (a line of a file an
``<attach>`` read) the name is looked up, among the names we write and those MuJoCo's compiler
makes (:mod:`typed_mjcf._model.compiled_names`). Where nothing identifies an element, the message
says so and which section the error concerns, never naming another element.
"""
from __future__ import annotations
from dataclasses import dataclass
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._text.files import CollectedFiles
from typed_mjcf.types import XmlElement as XmlNode

@dataclass(frozen=True, slots=True)
class Where:
    """What MuJoCo says about where an error happened."""
    tag: str | None = None
    name: str | None = None
    number: int | None = None
    line: int | None = None

def where(message: str) -> Where | None:
    """The last ``Element ...`` line of MuJoCo's message, read."""
    ...

@dataclass(frozen=True, slots=True)
class Location:
    """What the error is about: an element's path (``None`` if not known) and a sentence."""
    path: str | None
    note: str

def locate(model: ModelBase, message: str, collected: CollectedFiles) -> Location | None:
    """The element (or section) of ``model`` that MuJoCo's ``message`` is about, for the text
    written with ``collected``'s file names (as :func:`typed_mjcf._model.write.vfs_text` writes)."""
    ...

def written_nodes(model: ModelBase, collected: CollectedFiles,
                  ) -> tuple[XmlNode, list[tuple[XmlNode, Element]]]:
    """The model written as for MuJoCo (as :func:`locate` reads it, keyframes of composed
    models left out) and each node of it that is one of our elements, with that element, in
    document order (dm_control's debug dump)."""
    ...

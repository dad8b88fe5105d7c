# Generated from src/typed_mjcf/_dmcompat/element.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.element``: its element classes are typed-mjcf's, so ``isinstance(x,
element._ElementImpl)`` holds for every element and ``element.RootElement(model=...)``
makes a model."""
from __future__ import annotations
import typed_mjcf._generated.elements as _elements
from typed_mjcf._base import Element, ModelRoot
RootElement = _elements.RootElement
ModelRootBase = ModelRoot
__all__ = ["RootElement"]

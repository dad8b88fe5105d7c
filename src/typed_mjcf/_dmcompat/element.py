"""``dm_control.mjcf.element``: its element classes are typed-mjcf's, so ``isinstance(x,
element._ElementImpl)`` holds for every element and ``element.RootElement(model=...)``
makes a model."""

from __future__ import annotations

import typed_mjcf._generated.elements as _elements
from typed_mjcf._base import Element, ModelRoot
from typed_mjcf._core.tree import ElementList

RootElement = _elements.RootElement
_ElementImpl = Element  # dm_control's implementation class of every element
_AttachableElement = Element
_AttachmentFrame = _elements.Body  # attachment frames are bodies
_AttachmentFrameChild = Element
_DefaultElement = Element
_ElementListView = ElementList
ModelRootBase = ModelRoot

__all__ = ["RootElement"]

"""Every error typed-mjcf raises, and the warning it gives, by their public names.

Each derives from :class:`MjcfError` and from the builtin exception a Python user would
expect (``ValueError``, ``TypeError``, ``AttributeError``, ``OSError`` or ``RuntimeError``),
so code written for dm_control.mjcf catches them as it did. They are defined where the
runtime raises them (:mod:`typed_mjcf._core.errors`, and :mod:`typed_mjcf._model.validate` for the
findings of ``validate()``); this module is where users import them from, and the name
tracebacks show (``typed_mjcf.errors.ParseError``). ``typed_mjcf`` exports them too.
"""

from __future__ import annotations

from typed_mjcf._core.errors import (
    BindingError,
    ChildError,
    CompileError,
    DuplicateIdentifierError,
    ExportError,
    FileAccessError,
    FileReadError,
    IgnoredAttributeWarning,
    IllegalChildError,
    InvalidReferenceError,
    InvalidTypeError,
    InvalidValueError,
    MjcfError,
    NotParametricError,
    ParseError,
    PhysicsError,
    RenderError,
    UnbatchedWarning,
    UnknownAttributeError,
    did_you_mean,
    shown_as_public,
)
from typed_mjcf._model.validate import Finding, ValidationError

__all__ = [
    "BindingError",
    "ChildError",
    "CompileError",
    "DuplicateIdentifierError",
    "ExportError",
    "FileAccessError",
    "FileReadError",
    "Finding",
    "IgnoredAttributeWarning",
    "IllegalChildError",
    "InvalidReferenceError",
    "InvalidTypeError",
    "InvalidValueError",
    "MjcfError",
    "NotParametricError",
    "ParseError",
    "PhysicsError",
    "RenderError",
    "UnbatchedWarning",
    "UnknownAttributeError",
    "ValidationError",
    "did_you_mean",
]

# Tracebacks and reprs name a class by its __module__: the public one, not where it is defined.
shown_as_public(__name__, BindingError, ChildError, CompileError, DuplicateIdentifierError,
                ExportError, FileAccessError, FileReadError, Finding, IgnoredAttributeWarning,
                IllegalChildError, InvalidReferenceError, InvalidTypeError, InvalidValueError,
                MjcfError, NotParametricError, ParseError, PhysicsError, RenderError,
                UnbatchedWarning, UnknownAttributeError,
                ValidationError)

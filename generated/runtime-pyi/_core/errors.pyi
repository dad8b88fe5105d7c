# Generated from src/typed_mjcf/_core/errors.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The library's errors, defined below every other module (which raise them). Every one
derives from :class:`MjcfError` and from the builtin exception a Python user would expect
(``ValueError``, ``TypeError``, ``AttributeError`` or ``OSError``), so code written for
dm_control.mjcf catches them as it did. Users import them from :mod:`typed_mjcf.errors` (or
``typed_mjcf``), the name their tracebacks show."""
from __future__ import annotations
from collections.abc import Iterable

class MjcfError(Exception):
    """Base of every error typed-mjcf raises."""

class InvalidValueError(MjcfError, ValueError):
    """A value of the right Python type that MJCF does not allow."""

class InvalidTypeError(MjcfError, TypeError, ValueError):
    """A value of a Python type the attribute cannot take (also a ``ValueError``, which is
    what dm_control raises for every refused value)."""

class InvalidReferenceError(InvalidValueError, InvalidTypeError):
    """An element given where an element of another namespace (or a model) is expected."""

class UnknownAttributeError(MjcfError, AttributeError):
    """An attribute the element's grammar does not have."""

class ChildError(MjcfError, ValueError):
    """A change to the tree the model cannot take: a second child of a kind allowed once,
    an attachment that would clash, removing what cannot be removed."""

class IllegalChildError(ChildError, AttributeError):
    """A child the grammar does not allow under its parent (also an ``AttributeError``,
    as in dm_control), or an assignment to a child property."""

class DuplicateIdentifierError(InvalidValueError):
    """An identifier already taken in its namespace."""

class ParseError(MjcfError, ValueError):
    """MJCF text that cannot be read: malformed XML or something the grammar forbids."""
    source: str | None
    line: int | None
    detail: str
    def __init__(self, message: str, source: str | None = None, line: int | None = None) -> None: ...

class FileReadError(ParseError, OSError):
    """A file the model needs (the model, or a file it includes) cannot be read (also an
    ``OSError``, as dm_control's ``IOError``)."""

class FileAccessError(FileReadError, PermissionError):
    """A file the model names lies outside the folders it may read (by default its own
    folder; see :class:`~typed_mjcf.FileAccess`), or its files hold more bytes than allowed."""

class CompileError(MjcfError, ValueError):
    """MuJoCo refused to compile the model; ``path`` is the element its message is about,
    where one is known."""
    path: str | None
    def __init__(self, message: str, path: str | None = None) -> None: ...

class ExportError(MjcfError, ValueError):
    """The model cannot be written as MJCF (e.g. a reference to an unnamed element)."""

class BindingError(MjcfError, ValueError):
    """An element that cannot be bound to a physics (not compiled, of no bindable kind...)."""

class PhysicsError(MjcfError, RuntimeError):
    """The simulation reached an invalid state (MuJoCo raised a warning: NaNs, instability)."""

class RenderError(MjcfError, RuntimeError):
    """A picture cannot be made: no OpenGL back end works here (the message says what to
    install, or which setting to change)."""

class IgnoredAttributeWarning(UserWarning):
    """A file gives an element an attribute MuJoCo's reader ignores on it (``<frame>`` and
    ``<replicate>`` accept any attribute): it is dropped, as MuJoCo drops it."""
    source: str | None
    line: int | None
    path: str
    detail: str
    def __init__(self, detail: str, source: str | None = None, line: int | None = None,
                 path: str = "") -> None: ...

def did_you_mean(word: str, candidates: Iterable[str]) -> str:
    """`` (did you mean 'x'?)`` for a close misspelling, else an empty string."""
    ...

def shown_as_public(module: str, *classes: type) -> None:
    """Name ``classes`` after ``module`` (their ``__module__``), where users import them."""
    ...

class NotParametricError(MjcfError, ValueError):
    """An attribute that cannot be written into a compiled model per world (the compiler
    derives from it what writing it cannot): compile one model per world instead."""

class UnbatchedWarning(UserWarning):
    """Batched worlds (MuJoCo Warp) differ in a field the back end holds once for all
    worlds: every world keeps the compiled model's value."""

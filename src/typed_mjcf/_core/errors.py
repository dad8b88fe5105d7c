"""The library's errors, defined below every other module (which raise them). Every one
derives from :class:`MjcfError` and from the builtin exception a Python user would expect
(``ValueError``, ``TypeError``, ``AttributeError`` or ``OSError``), so code written for
dm_control.mjcf catches them as it did. Users import them from :mod:`typed_mjcf.errors` (or
``typed_mjcf``), the name their tracebacks show."""

from __future__ import annotations

import difflib
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

    source: str | None  # the file (or description) the text came from
    line: int | None
    detail: str  # the message without its location

    def __init__(self, message: str, source: str | None = None, line: int | None = None) -> None:
        self.source = source
        self.line = line
        self.detail = message
        super().__init__(_where(source, line) + message)


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

    def __init__(self, message: str, path: str | None = None) -> None:
        super().__init__(message)
        self.path = path


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

    source: str | None  # the file (None: text given in memory)
    line: int | None
    path: str  # the element's path in the model
    detail: str  # the message without its location

    def __init__(self, detail: str, source: str | None = None, line: int | None = None,
                 path: str = "") -> None:
        self.source, self.line, self.path, self.detail = source, line, path, detail
        super().__init__(_where(source, line) + detail)


def _where(source: str | None, line: int | None) -> str:
    """``file:line: `` (or what of it is known) to start a message with."""
    if source is not None:
        return f"{source}:{line}: " if line is not None else f"{source}: "
    return f"line {line}: " if line is not None else ""


def did_you_mean(word: str, candidates: Iterable[str]) -> str:
    """`` (did you mean 'x'?)`` for a close misspelling, else an empty string."""
    matches = difflib.get_close_matches(word.lower(), list(candidates), n=1, cutoff=0.6)
    return f" (did you mean {matches[0]!r}?)" if matches else ""


def shown_as_public(module: str, *classes: type) -> None:
    """Name ``classes`` after ``module`` (their ``__module__``), where users import them."""
    for cls in classes:
        cls.__module__ = module


class NotParametricError(MjcfError, ValueError):
    """An attribute that cannot be written into a compiled model per world (the compiler
    derives from it what writing it cannot): compile one model per world instead."""


class UnbatchedWarning(UserWarning):
    """Batched worlds (MuJoCo Warp) differ in a field the back end holds once for all
    worlds: every world keeps the compiled model's value."""

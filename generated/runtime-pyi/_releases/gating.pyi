# Generated from src/typed_mjcf/_releases/gating.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Which MuJoCo release's grammar the runtime follows: the installed one's.

The classes describe the newest release covered (the typing surface); the generated table
``releases.py`` says, per row, which releases have each attribute, child and keyword where
not all do, and each release's type of an attribute (kind, value count, default, ...) where
it is not the newest's. The release is chosen once, at import, from the installed ``mujoco``'s package
metadata (``mujoco`` itself is not imported, nor pathlib or importlib.metadata): the newest covered release not newer than the
installed one. :func:`restrict` then takes out of the grammar tables what that release lacks,
and retypes what it types otherwise, so the hot paths (parse, assignment, export) pay
nothing; the error paths ask :func:`note` why a name is unknown ("needs MuJoCo >= 4.0.0;
installed 3.17.0") and :func:`value_note` why a value is refused.
"""
from __future__ import annotations
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Final, cast
from typed_mjcf._core.codecs import Codec, Rejected
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.grammar import ElementSpec
from typed_mjcf._core.tree import Element

def version_key(version: str) -> tuple[int, ...]: ...

def installed_mujoco() -> str | None:
    """The installed ``mujoco``'s release, from the ``*.dist-info`` beside the module (no
    import of MuJoCo; importlib.metadata would cost more than the rest of this module)."""
    ...

def choose(installed: str | None) -> str:
    """The covered release whose grammar applies: the newest not newer than ``installed``
    (the oldest for an older MuJoCo, the newest when MuJoCo is not installed)."""
    ...
INSTALLED: Final = installed_mujoco()
RELEASE: Final = choose(INSTALLED)

def covered(installed: str | None = INSTALLED) -> bool:
    """Whether ``installed`` is within the releases the bindings cover (same major and
    minor as one of them, or between the oldest and the newest)."""
    ...

def needs_at_least(first: str) -> str:
    """"needs MuJoCo >= first; installed Y": what the release in use lacks came in ``first``."""
    ...

def note(spec: ElementSpec, name: str) -> str | None:
    """Why ``name`` (an attribute, a child's tag or Python name, or ``add_<tag>``) is not on
    ``spec``'s row with the release in use: "needs MuJoCo >= X; installed Y"; None when the
    release is not the reason."""
    ...

def value_note(spec: ElementSpec, attribute: AttributeSpec, value: object) -> str | None:
    """Why ``value`` is refused, when other releases covered take it (a keyword they have,
    a value of their kind or count): "needs MuJoCo >= 4.0.0; installed 3.17.0"."""
    ...

def newest_type(spec: ElementSpec, attribute: AttributeSpec) -> AttributeSpec:
    """``attribute`` as the newest release (the typing surface) types it: itself unless
    the release in use types it otherwise."""
    ...

def newest_keywords(spec: ElementSpec, attribute: AttributeSpec) -> tuple[str, ...]:
    """``attribute``'s keywords in the newest release (the typing surface's)."""
    ...

def release_codec(spec: ElementSpec, newest: AttributeSpec, release: str) -> Codec:
    """The codec of ``newest`` (an attribute as the newest types it) in ``release``."""
    ...

def restrict(classes: Mapping[str, type[Element]], release: str = RELEASE) -> None:
    """Take out of every row what ``release`` lacks: attributes (and their properties),
    children (their lists and ``add_<tag>()``); retype what it types otherwise: keywords,
    kinds, value counts, defaults (the attribute's spec and codec become the release's)."""
    ...

def describe() -> str:
    """For ``--version``: the releases covered and the one installed."""
    ...

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

import copy
import dataclasses
import os
import re
from collections.abc import Callable, Mapping
from importlib.util import find_spec
from typing import TYPE_CHECKING, Final, cast

from typed_mjcf._core.codecs import Codec, Rejected
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.rows import ReleaseType, release_type
from typed_mjcf._generated.releases import (
    ATTRIBUTES,
    CHILDREN,
    KEYWORDS,
    RELEASES,
    REMOVED,
    TYPES,
)

if TYPE_CHECKING:
    from typed_mjcf._core.grammar import ElementSpec
    from typed_mjcf._core.tree import Element

# the distributions that install the `mujoco` module: MuJoCo 4's engine comes as
# mujoco-core (with `mujoco` a meta-package over it), MuJoCo 3 as `mujoco` alone
_DISTRIBUTIONS: Final = ("mujoco_core", "mujoco")


def version_key(version: str) -> tuple[int, ...]:
    return tuple(int(part) for part in re.findall(r"\d+", version))


def installed_mujoco() -> str | None:
    """The installed ``mujoco``'s release, from the ``*.dist-info`` beside the module (no
    import of MuJoCo; importlib.metadata would cost more than the rest of this module)."""
    try:
        spec = find_spec("mujoco")
    except (ImportError, ValueError):
        return None
    if spec is None or spec.origin is None:
        return None
    site = os.path.dirname(os.path.dirname(spec.origin))
    try:
        names = os.listdir(site)
    except OSError:
        return None
    for distribution in _DISTRIBUTIONS:
        found = [name[len(distribution) + 1 : -len(".dist-info")] for name in names
                 if name.startswith(distribution + "-") and name.endswith(".dist-info")]
        if found:
            return max(found, key=version_key)
    return None


def choose(installed: str | None) -> str:
    """The covered release whose grammar applies: the newest not newer than ``installed``
    (the oldest for an older MuJoCo, the newest when MuJoCo is not installed)."""
    if installed is None:
        return RELEASES[-1]
    key = version_key(installed)
    fitting = [r for r in RELEASES if version_key(r) <= key]
    return fitting[-1] if fitting else RELEASES[0]


INSTALLED: Final = installed_mujoco()
RELEASE: Final = choose(INSTALLED)


def covered(installed: str | None = INSTALLED) -> bool:
    """Whether ``installed`` is within the releases the bindings cover (same major and
    minor as one of them, or between the oldest and the newest)."""
    if installed is None:
        return False
    key = version_key(installed)
    return version_key(RELEASES[0]) <= key and key[:2] <= version_key(RELEASES[-1])[:2]


def needs_at_least(first: str) -> str:
    """"needs MuJoCo >= first; installed Y": what the release in use lacks came in ``first``."""
    return f"needs MuJoCo >= {first}; installed {INSTALLED or 'none'}"


def _needs(having: tuple[str, ...]) -> str:
    """``having`` (the releases with a name) against the one in use, in words."""
    if having and having == RELEASES[RELEASES.index(having[0]):]:
        return needs_at_least(having[0])
    return f"is in MuJoCo {', '.join(having)} only; installed {INSTALLED or 'none'}"


# what RELEASE lacks, filled by restrict(): row -> name (XML or Python) -> the releases having it
_GONE_ATTRIBUTES: dict[str, dict[str, tuple[str, ...]]] = {}
_GONE_CHILDREN: dict[str, dict[str, tuple[str, ...]]] = {}


def note(spec: ElementSpec, name: str) -> str | None:
    """Why ``name`` (an attribute, a child's tag or Python name, or ``add_<tag>``) is not on
    ``spec``'s row with the release in use: "needs MuJoCo >= X; installed Y"; None when the
    release is not the reason."""
    having = _GONE_ATTRIBUTES.get(spec.row, {}).get(name)
    if having is None:
        children = _GONE_CHILDREN.get(spec.row, {})
        having = children.get(name) or children.get(name.removeprefix("add_"))
    if having is None:
        return _removed(spec, name.removeprefix("add_"))
    return _needs(having)


def _removed(spec: ElementSpec, tag: str) -> str | None:
    """Why ``tag``, a child only older releases take (no class has it), is refused."""
    having = REMOVED.get(spec.row, {}).get(tag)
    if having is None:
        return None
    gone = next(r for r in RELEASES if version_key(r) > version_key(having[-1]))
    shown = INSTALLED or "none"
    if RELEASE in having:
        return (f"is in MuJoCo {', '.join(having)} only, and typed-mjcf has no bindings for it "
                f"(its typed API is MuJoCo {RELEASES[-1]}'s); installed {shown}")
    if version_key(RELEASE) > version_key(having[-1]):
        return f"was removed in MuJoCo {gone}; installed {shown}"
    return f"is in MuJoCo {', '.join(having)} only; installed {shown}"


def value_note(spec: ElementSpec, attribute: AttributeSpec, value: object) -> str | None:
    """Why ``value`` is refused, when other releases covered take it (a keyword they have,
    a value of their kind or count): "needs MuJoCo >= 4.0.0; installed 3.17.0"."""
    if attribute.name not in TYPES.get(spec.row, _NONE) and \
            attribute.name not in KEYWORDS.get(spec.row, _NONE):
        return None  # every release types it alike
    newest = newest_type(spec, attribute)
    having = tuple(r for r in RELEASES if _takes(release_codec(spec, newest, r), value))
    return _needs(having) if having else None


def _takes(codec: Codec, value: object) -> bool:
    try:
        codec.accept(value)
    except Rejected:
        return False
    return True


_NONE: Final[dict[str, object]] = {}
# row, attribute -> the attribute as the newest types it, for those restrict() retyped
_NEWEST: dict[tuple[str, str], AttributeSpec] = {}


def newest_type(spec: ElementSpec, attribute: AttributeSpec) -> AttributeSpec:
    """``attribute`` as the newest release (the typing surface) types it: itself unless
    the release in use types it otherwise."""
    return _NEWEST.get((spec.row, attribute.name), attribute)


def newest_keywords(spec: ElementSpec, attribute: AttributeSpec) -> tuple[str, ...]:
    """``attribute``'s keywords in the newest release (the typing surface's)."""
    return newest_type(spec, attribute).keywords


def release_codec(spec: ElementSpec, newest: AttributeSpec, release: str) -> Codec:
    """The codec of ``newest`` (an attribute as the newest types it) in ``release``."""
    return _typed(newest, _release_type(spec, newest, release)).codec


def _release_type(spec: ElementSpec, newest: AttributeSpec, release: str) -> ReleaseType:
    """``release``'s type of ``newest`` (an attribute as the newest types it)."""
    found = TYPES.get(spec.row, {}).get(newest.name, {}).get(release)
    if found is not None:
        return found
    own = release_type(newest)
    words = KEYWORDS.get(spec.row, {}).get(newest.name, {}).get(release)
    return own if words is None else own._replace(keywords=words)


def _typed(newest: AttributeSpec, typed_as: ReleaseType) -> AttributeSpec:
    """A copy of ``newest`` typed as ``typed_as`` says (what the kind does not fix, such as a
    keyword's words taken alone or a number's bounds, kept when the kind is the newest's)."""
    same = typed_as.kind == newest.kind
    typed = dataclasses.replace(
        newest, **typed_as._asdict(), computed=newest.computed and typed_as.default is None,
        alone=newest.alone if same else (), ordered=newest.ordered and same,
        namespace_from=newest.namespace_from if same else None,
        pattern=newest.pattern if same else None, bounds=newest.bounds if same else (),
        off=newest.off if same else ())
    typed.index = newest.index
    if newest.name_list is not None and same:
        typed.mark_name_list(newest.name_list)
    return typed


def restrict(classes: Mapping[str, type[Element]], release: str = RELEASE) -> None:
    """Take out of every row what ``release`` lacks: attributes (and their properties),
    children (their lists and ``add_<tag>()``); retype what it types otherwise: keywords,
    kinds, value counts, defaults (the attribute's spec and codec become the release's)."""
    for cls in classes.values():
        spec = cls.spec
        gone = {name: having for name, having in ATTRIBUTES.get(spec.row, {}).items()
                if release not in having}
        if gone:
            _drop_attributes(cls, spec, gone)
        for table in (TYPES, KEYWORDS):
            for name, by_release in table.get(spec.row, {}).items():
                attribute = spec.by_name.get(name)
                if attribute is None or release not in by_release or (spec.row, name) in _NEWEST:
                    continue
                newest = copy.copy(attribute)
                typed = _typed(newest, _release_type(spec, newest, release))
                _NEWEST[(spec.row, name)] = newest
                _retype(cls, spec, attribute, typed)
        for tag, having in CHILDREN.get(spec.row, {}).items():
            child = spec.children.get(tag)
            if release in having or child is None:
                continue
            del spec.children[tag]
            for member in (child.py_name, "add_" + tag):
                if member in cls.__dict__:
                    delattr(cls, member)
            found = _GONE_CHILDREN.setdefault(spec.row, {})
            found[tag] = found[child.py_name] = having


def _drop_attributes(cls: type[Element], spec: ElementSpec,
                     gone: dict[str, tuple[str, ...]]) -> None:
    dropped = [a for a in spec.attributes.values() if a.name in gone]
    spec.attributes = {name: a for name, a in spec.attributes.items() if name not in gone}
    spec.references = tuple(a for a in spec.references if a.name not in gone)
    found = _GONE_ATTRIBUTES.setdefault(spec.row, {})
    for attribute in dropped:
        del spec.by_name[attribute.name]
        del spec.order[attribute.name]
        for key in [k for k, a in spec.by_key.items() if a is attribute]:
            del spec.by_key[key]
            found[key] = gone[attribute.name]
            if key in cls.__dict__:
                delattr(cls, key)
        found[attribute.name] = gone[attribute.name]
    spec.plans.clear()


def _retype(cls: type[Element], spec: ElementSpec, attribute: AttributeSpec,
            typed: AttributeSpec) -> None:
    """Make ``attribute`` (the object every table of the row holds) ``typed``, and the
    property reading it follow (it keeps its own copies of the codec and the kind)."""
    for slot in (f.name for f in dataclasses.fields(typed)):  # the row and what it derives
        setattr(attribute, slot, getattr(typed, slot))
    spec.references = tuple(a for a in spec.attributes.values() if a.is_reference)
    spec.plans.clear()
    descriptor = cls.__dict__.get(attribute.py_name)
    if descriptor is not None and hasattr(descriptor, "codec"):  # the property
        make = cast("Callable[[AttributeSpec], object]", type(descriptor))
        setattr(cls, attribute.py_name, make(attribute))


def describe() -> str:
    """For ``--version``: the releases covered and the one installed."""
    installed = INSTALLED or "not installed"
    if INSTALLED is not None and RELEASE != INSTALLED:
        installed += f" (its grammar: {RELEASE}'s" + (
            ")" if covered() else "; not a release typed-mjcf covers)")
    return f"MuJoCo releases covered: {', '.join(RELEASES)}; installed: {installed}"


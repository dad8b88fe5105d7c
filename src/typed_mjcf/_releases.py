"""Which MuJoCo release's grammar the runtime follows: the installed one's.

The classes describe the newest release covered (the typing surface); the generated table
``releases.py`` says, per row, which releases have each attribute, child and keyword where
not all do. The release is chosen once, at import, from the installed ``mujoco``'s package
metadata (``mujoco`` itself is not imported, nor pathlib or importlib.metadata): the newest covered release not newer than the
installed one. :func:`restrict` then takes out of the grammar tables what that release lacks,
so the hot paths (parse, assignment, export) pay nothing; the error paths ask :func:`note`
why a name is unknown ("needs MuJoCo >= 4.0.0; installed 3.17.0").
"""

from __future__ import annotations

import os
import re
from collections.abc import Mapping
from importlib.util import find_spec
from typing import TYPE_CHECKING, Final

from typed_mjcf._codecs import make_codec
from typed_mjcf._generated.releases import ATTRIBUTES, CHILDREN, KEYWORDS, RELEASES

if TYPE_CHECKING:
    from typed_mjcf._grammar import AttributeSpec, ElementSpec
    from typed_mjcf._tree import Element

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


def _needs(having: tuple[str, ...]) -> str:
    """``having`` (the releases with a name) against the one in use, in words."""
    shown = INSTALLED or "none"
    if having and having == RELEASES[RELEASES.index(having[0]):]:
        return f"needs MuJoCo >= {having[0]}; installed {shown}"
    return f"is in MuJoCo {', '.join(having)} only; installed {shown}"


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
    return None if having is None else _needs(having)


def keyword_note(spec: ElementSpec, attribute: AttributeSpec, value: object) -> str | None:
    """Why the keyword ``value`` is refused, when another release covered takes it."""
    by_release = KEYWORDS.get(spec.row, {}).get(attribute.name)
    if by_release is None or not isinstance(value, str):
        return None
    words = value.split() if attribute.kind == "flags" else [value]
    newest = newest_keywords(spec, attribute)
    for word in words:
        if word in attribute.keywords:
            continue
        having = tuple(r for r in RELEASES if word in by_release.get(r, newest))
        if having:
            return f"{word!r} {_needs(having)}"
    return None


_NEWEST_KEYWORDS: dict[tuple[str, str], tuple[str, ...]] = {}


def newest_keywords(spec: ElementSpec, attribute: AttributeSpec) -> tuple[str, ...]:
    """``attribute``'s keywords in the newest release (the typing surface's)."""
    return _NEWEST_KEYWORDS.get((spec.row, attribute.name), attribute.keywords)


def restrict(classes: Mapping[str, type[Element]], release: str = RELEASE) -> None:
    """Take out of every row what ``release`` lacks: attributes (and their properties),
    children (their lists and ``add_<tag>()``), keywords (the codec is the release's)."""
    for cls in classes.values():
        spec = cls.spec
        gone = {name: having for name, having in ATTRIBUTES.get(spec.row, {}).items()
                if release not in having}
        if gone:
            _drop_attributes(cls, spec, gone)
        for name, by_release in KEYWORDS.get(spec.row, {}).items():
            words = by_release.get(release)
            attribute = spec.by_name.get(name)
            if words is not None and attribute is not None:
                _NEWEST_KEYWORDS[(spec.row, name)] = attribute.keywords
                _set_keywords(cls, attribute, words)
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


def _set_keywords(cls: type[Element], attribute: AttributeSpec, words: tuple[str, ...]) -> None:
    attribute.keywords = words
    attribute.codec = make_codec(attribute.kind, dtype=attribute.dtype,
                                 is_array=attribute.is_array, lo=attribute.lo, hi=attribute.hi,
                                 keywords=words, pattern=attribute.pattern,
                                 alone=attribute.alone, ordered=attribute.ordered)
    descriptor = cls.__dict__.get(attribute.py_name)
    if descriptor is not None and hasattr(descriptor, "codec"):  # the property's own copy
        setattr(descriptor, "codec", attribute.codec)


def describe() -> str:
    """For ``--version``: the releases covered and the one installed."""
    installed = INSTALLED or "not installed"
    if INSTALLED is not None and RELEASE != INSTALLED:
        installed += f" (its grammar: {RELEASE}'s" + (
            ")" if covered() else "; not a release typed-mjcf covers)")
    return f"MuJoCo releases covered: {', '.join(RELEASES)}; installed: {installed}"


"""The MuJoCo releases the bindings cover, and what each one's grammar lacks.

``schema/mjcf.json`` describes the newest release: the typing surface. Each older release's
grammar is ``schema/releases/<version>.json``, the same IR as ``python -m codegen generate``
writes under that MuJoCo (the newest schema synced with the older wheel; never edited by
hand). :func:`gates` compares them with the newest and :func:`render_table` writes the
result as ``generated/typed_mjcf_generated/releases.py``: per row, the attributes and children
not every release has (the releases that have them), and the keyword sets that differ. The
runtime picks the installed release's gates once, at import (``typed_mjcf._releases``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from codegen import ir

RELEASES_DIR = ir.SCHEMA_DIR / "releases"

Releases = tuple[str, ...]


def version_key(version: str) -> tuple[int, ...]:
    """``"3.17.0"`` -> ``(3, 17, 0)``: releases in numeric order."""
    return tuple(int(part) for part in re.findall(r"\d+", version))


def release_path(version: str, directory: Path = RELEASES_DIR) -> Path:
    return directory / f"{version}.json"


def load_releases(directory: Path = RELEASES_DIR) -> dict[str, ir.Schema]:
    """Every older release's grammar in ``directory``, oldest first."""
    found = {path.stem: ir.load(path) for path in directory.glob("*.json")}
    return {version: found[version] for version in sorted(found, key=version_key)}


@dataclass
class Gates:
    """What the releases lack, against the newest (``releases[-1]``)."""

    releases: Releases  # every release covered, oldest first
    # row -> attribute -> the releases that have it (only attributes some release lacks)
    attributes: dict[str, dict[str, Releases]] = field(default_factory=lambda: {})
    # row -> child tag -> the releases where the row takes it (only where some does not)
    children: dict[str, dict[str, Releases]] = field(default_factory=lambda: {})
    # row -> attribute -> release -> its keywords (only where they differ from the newest's)
    keywords: dict[str, dict[str, dict[str, tuple[str, ...]]]] = field(
        default_factory=lambda: {})

    def attribute_releases(self, row: str, attribute: str) -> Releases | None:
        """The releases that have ``row``'s ``attribute``, or None when all do."""
        return self.attributes.get(row, {}).get(attribute)


def _keywords(schema: ir.Schema, a: ir.AttributeDef) -> tuple[str, ...]:
    if a.enum is None or a.enum not in schema.enums:
        return ()
    return tuple(schema.enums[a.enum].keywords)


def gates(newest: ir.Schema, older: dict[str, ir.Schema]) -> Gates:
    """Compare each older release's grammar with the newest's (release files not older
    than ``newest`` are left out: a new newest is being generated)."""
    ordered = sorted((v for v in older if version_key(v) < version_key(newest.mujoco_version)),
                     key=version_key)
    result = Gates((*ordered, newest.mujoco_version))
    for row, el in sorted(newest.elements.items()):
        for a in el.attributes:
            having: list[str] = []
            for version in ordered:
                old = older[version].elements.get(row)
                match = next((o for o in old.attributes if o.name == a.name), None) \
                    if old is not None else None
                if match is None:
                    continue
                having.append(version)
                if a.kind in ("keyword", "flags") and match.kind == a.kind:
                    words = _keywords(older[version], match)
                    if words and words != _keywords(newest, a):
                        result.keywords.setdefault(row, {}).setdefault(a.name, {})[
                            version] = words
            if len(having) < len(ordered):
                result.attributes.setdefault(row, {})[a.name] = (
                    *having, newest.mujoco_version)
        for child in el.children:
            tag = newest.elements[child.element].tag
            having = [version for version in ordered
                      if (old := older[version].elements.get(row)) is not None
                      and any(c.element == child.element for c in old.children)]
            if len(having) < len(ordered):
                result.children.setdefault(row, {})[tag] = (*having, newest.mujoco_version)
    return result


def availability(releases: Releases, covered: Releases) -> str:
    """``releases`` (a subset of ``covered``) in words for an attribute's doc."""
    if releases and releases == covered[covered.index(releases[0]):]:
        return f"MuJoCo >= {releases[0]}"
    return "MuJoCo " + ", ".join(releases) + " only"


def render_table(result: Gates, newest: str) -> str:
    """The generated module ``releases.py``: the gates as plain literals."""
    def block(name: str, comment: str, annotation: str, value: object) -> str:
        return f"# {comment}\n{name}: Final[{annotation}] = {value!r}\n"

    return "\n".join([
        (f"# Generated by typed-mjcf codegen from schema/mjcf.json (MuJoCo {newest}) and "
         "schema/releases/."),
        "# Do not edit: change schema/ or codegen/ and run `nox -s generate`.",
        ('"""The MuJoCo releases the bindings cover and what each one\'s grammar lacks '
         '(``typed_mjcf._releases`` applies them)."""'),
        "",
        "from typing import Final",
        "",
        block("RELEASES", "every release covered, oldest first; the last is the typing surface",
              "tuple[str, ...]", result.releases),
        block("ATTRIBUTES", "row -> attribute -> the releases that have it (where some lack it)",
              "dict[str, dict[str, tuple[str, ...]]]", result.attributes),
        block("CHILDREN", "row -> child tag -> the releases where the row takes it",
              "dict[str, dict[str, tuple[str, ...]]]", result.children),
        block("KEYWORDS", "row -> attribute -> release -> its keywords, where not the newest's",
              "dict[str, dict[str, dict[str, tuple[str, ...]]]]", result.keywords),
    ])


Notes = dict[str, dict[str, str]]  # row -> attribute -> the releases that have it, in words


def notes(result: Gates) -> Notes:
    """For the attribute docs: the releases having each attribute that not all releases have."""
    return {row: {name: availability(having, result.releases) for name, having in attrs.items()}
            for row, attrs in result.attributes.items()}


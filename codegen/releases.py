"""The MuJoCo releases the bindings cover, and what each one's grammar lacks.

``schema/mjcf.json`` describes the newest release: the typing surface. Each older release's
grammar is ``schema/releases/<version>.json``, the same IR as ``python -m codegen generate``
writes under that MuJoCo (the newest schema synced with the older wheel; never edited by
hand). :func:`gates` compares them with the newest and :func:`render_table` writes the
result as ``generated/typed_mjcf_generated/releases.py``: per row, the attributes and children
not every release has (the releases that have them), the keyword sets that differ, and the
attributes whose type differs (kind, number type, value count, keywords, default or
namespace: what codegen/drift.py probes). The runtime picks the installed release's gates
once, at import (``typed_mjcf._releases.gating``).
"""

from __future__ import annotations

import copy
import dataclasses
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import cast

from codegen import ir, rows
from codegen.errors import FactsError
from codegen.facts import AttributeOverride, Facts, attribute_entry

RELEASES_DIR = ir.SCHEMA_DIR / "releases"
# [[attribute]] entries (facts.toml's) that hold for the releases before ``until`` instead of
# facts.toml's entry for that attribute (which types the newest): what the probe cannot type
RELEASE_FACTS = RELEASES_DIR / "facts.toml"

Releases = tuple[str, ...]
# An attribute's type in one release: the fields of typed_mjcf._core.rows.ReleaseType (those
# at their default left out). Bounds and ``required`` are not among them: the probe does not
# measure them, so the newest's stand for every release.
TypeFields = dict[str, object]


def version_key(version: str) -> tuple[int, ...]:
    """``"3.17.0"`` -> ``(3, 17, 0)``: releases in numeric order."""
    return tuple(int(part) for part in re.findall(r"\d+", version))


def release_path(version: str, directory: Path = RELEASES_DIR) -> Path:
    return directory / f"{version}.json"


def release_facts(facts: Facts, version: str, path: Path = RELEASE_FACTS) -> Facts:
    """``facts`` for an older ``version``: schema/releases/facts.toml's entries for releases
    before their ``until`` replace facts.toml's entries for the same attributes."""
    if not path.exists():
        return facts
    try:
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise FactsError(f"{path}: {exc}") from None
    entries = raw.get("attribute", [])
    if set(raw) - {"attribute"} or not isinstance(entries, list):
        raise FactsError(f"{path}: expected [[attribute]] entries only")
    older: list[AttributeOverride] = []
    for at, entry in enumerate(cast("list[object]", entries), 1):
        where = f"{path}: [[attribute]] #{at}"
        if not isinstance(entry, dict) or not isinstance(
                until := cast("dict[str, object]", entry).get("until"), str):
            raise FactsError(f'{where}: expected until = "<the first release it does not '
                             'hold for>"')
        rest = {k: v for k, v in cast("dict[str, object]", entry).items() if k != "until"}
        if version_key(version) < version_key(until):
            older.append(attribute_entry(rest, where))
    replaced = {(o.element, o.name) for o in older}
    return dataclasses.replace(facts, attributes=[
        *(o for o in facts.attributes if (o.element, o.name) not in replaced), *older])


def with_keywords_of(newest: ir.Schema, previous: ir.Schema | None) -> ir.Schema:
    """``newest`` with the keywords ``previous`` (the release file being regenerated) has in
    its enums of the same name added: candidates for the drift probe, which keeps those the
    release's reader takes (a keyword a later release dropped is in no newer source)."""
    if previous is None:
        return newest
    found = copy.deepcopy(newest)
    for name, enum in found.enums.items():
        old = previous.enums.get(name)
        if old is None:
            continue
        known = set(enum.keywords)
        extra = [(k, v) for k, v in old.values if k not in known]
        if extra:  # in the previous file's order, the newest's after
            order = {k: i for i, k in enumerate(old.keywords)}
            enum.values = sorted([*enum.values, *extra],
                                 key=lambda kv: order.get(kv[0], len(order)))
    return found


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
    # row -> child tag -> the older releases where the row takes it, for children whose
    # rows only older releases have (<composite>): the newest has no class for them
    removed: dict[str, dict[str, Releases]] = field(default_factory=lambda: {})
    # row -> attribute -> release -> its type (only where more than the keywords differ)
    types: dict[str, dict[str, dict[str, TypeFields]]] = field(default_factory=lambda: {})

    def attribute_releases(self, row: str, attribute: str) -> Releases | None:
        """The releases that have ``row``'s ``attribute``, or None when all do."""
        return self.attributes.get(row, {}).get(attribute)


def _keywords(schema: ir.Schema, a: ir.AttributeDef) -> tuple[str, ...]:
    return rows.keywords(schema, a)


def type_fields(schema: ir.Schema, a: ir.AttributeDef) -> TypeFields:
    """What the runtime's AttributeSpec is built from, for ``a`` as ``schema`` types it."""
    return rows.release_values(schema, a)


def type_row(fields: TypeFields) -> rows.ReleaseType:
    """``fields`` as the generated table holds them (``typed_mjcf._core.rows.ReleaseType``)."""
    defaults = rows.ReleaseType._field_defaults
    return rows.ReleaseType._make(fields.get(name, defaults.get(name))
                                  for name in rows.ReleaseType._fields)


def _differs(newest: TypeFields, old: TypeFields) -> bool:
    """More than the keywords differ (keywords alone are :attr:`Gates.keywords`)."""
    def rest(fields: TypeFields) -> TypeFields:
        return {k: v for k, v in fields.items() if k != "keywords"}
    return rest(newest) != rest(old)


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
                old_type = type_fields(older[version], match)
                if "default" not in old_type and a.default is not None and match.kind == a.kind:
                    # a release file written before defaults were probed: the newest's stands
                    old_type["default"] = a.default
                if _differs(type_fields(newest, a), old_type):
                    result.types.setdefault(row, {}).setdefault(a.name, {})[version] = old_type
                elif a.kind in ("keyword", "flags") and match.kind == a.kind:
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
    for version in ordered:
        for row, old_row in sorted(older[version].elements.items()):
            if row not in newest.elements:
                continue
            for child in old_row.children:
                if child.element not in newest.elements:
                    tag = older[version].elements[child.element].tag
                    found = result.removed.setdefault(row, {}).setdefault(tag, ())
                    result.removed[row][tag] = (*found, version)
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
         '(``typed_mjcf._releases.gating`` applies them)."""'),
        "",
        "from typing import Final",
        "",
        "from typed_mjcf._core.rows import ReleaseType",
        "",
        block("RELEASES", "every release covered, oldest first; the last is the typing surface",
              "tuple[str, ...]", result.releases),
        block("ATTRIBUTES", "row -> attribute -> the releases that have it (where some lack it)",
              "dict[str, dict[str, tuple[str, ...]]]", result.attributes),
        block("CHILDREN", "row -> child tag -> the releases where the row takes it",
              "dict[str, dict[str, tuple[str, ...]]]", result.children),
        block("KEYWORDS", "row -> attribute -> release -> its keywords, where not the newest's",
              "dict[str, dict[str, dict[str, tuple[str, ...]]]]", result.keywords),
        block("REMOVED", "row -> child tag -> the older releases where the row takes it, "
              "for rows only older releases have (no class: refused)",
              "dict[str, dict[str, tuple[str, ...]]]", result.removed),
        block("TYPES", "row -> attribute -> release -> its type, where more than the "
              "keywords differ",
              "dict[str, dict[str, dict[str, ReleaseType]]]",
              {row: {name: {version: rows.Source(rows.call("ReleaseType", rows.RELEASE, fields))
                            for version, fields in by.items()}
                     for name, by in attrs.items()} for row, attrs in result.types.items()}),
    ])


Notes = dict[str, dict[str, str]]  # row -> attribute -> the releases that have it, in words


def notes(result: Gates) -> Notes:
    """For the attribute docs: the releases having each attribute that not all releases have,
    and the releases typing it otherwise than the newest (``MuJoCo 3.17.0: int, default "1"``)."""
    found = {row: {name: availability(having, result.releases) for name, having in attrs.items()}
             for row, attrs in result.attributes.items()}
    for row, attrs in result.types.items():
        for name, by_release in attrs.items():
            text = "; in ".join(f"MuJoCo {', '.join(group)}: {describe(fields)}"
                                for fields, group in grouped(by_release))
            found.setdefault(row, {})[name] = (
                f"{found[row][name]}; in {text}" if name in found.get(row, {}) else text)
    return found


def grouped(by_release: dict[str, TypeFields]) -> list[tuple[TypeFields, list[str]]]:
    """The releases sharing one type, oldest first."""
    groups: list[tuple[TypeFields, list[str]]] = []
    for version, fields in by_release.items():
        same = next((g for f, g in groups if f == fields), None)
        if same is None:
            groups.append((fields, [version]))
        else:
            same.append(version)
    return groups


def describe(fields: TypeFields) -> str:
    """One release's type in words: ``int, default "1"``, ``ref<material>``."""
    kind = str(fields["kind"])
    if "keywords" in fields:
        words = cast(tuple[str, ...], fields["keywords"])
        text = f"{kind} {'|'.join(words)}"
        numbers = cast(tuple[tuple[str, int], ...], fields.get("numbers", ()))
        if numbers:
            text += f" (or {'|'.join(str(n) for _, n in numbers)})"
    elif "namespace" in fields:
        text = f"{kind}<{fields['namespace']}>"
    else:
        text = str(fields.get("dtype", kind))
    arity = cast("tuple[int, int | None] | None", fields.get("arity"))
    if arity is not None:
        lo, hi = arity
        text += (f"[{lo}]" if lo == hi else f"[{lo}..{'' if hi is None else hi}]")
    if "default" in fields:
        text += f', default "{fields["default"]}"'
    return text


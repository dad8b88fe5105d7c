"""``typed-mjcf diff``: what differs between two models, element by element.

Elements are aligned by name (the same tag and name, wherever they are), unnamed ones under
aligned parents by their order among children of their tag (an element inserted or deleted
among them is found as such, by comparing the attributes of the sequences). Values are
compared in their canonical form, so formatting, attribute order and the spelling of numbers
never show; with ``--resolved``, each attribute is compared as MuJoCo will use it, defaults
applied.
"""

from __future__ import annotations

import argparse
import difflib
import itertools
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from typed_mjcf import tooling
from typed_mjcf.cli._common import BAD_INPUT, FOUND, OK, BadInput, error, load, shown, where
from typed_mjcf.cli._values import stored_text, value_text
from typed_mjcf.cli.render import size, write_diff_picture
from typed_mjcf.errors import MjcfError
from typed_mjcf.tooling import Element, iter_written, resolve_all, written_children

NAME = "diff"
HELP = "show how two models differ, element by element (exit 1 if they do)"
DESCRIPTION = """\
Compare two models semantically: elements are aligned by name (or, unnamed, by their place
among their parent's children of the same tag), and each difference is one line:

  + PATH: <element ...>                       added in B
  - PATH: <element ...>                       removed from A
  ~ PATH: ATTRIBUTE "A's value" -> "B's value"  changed (unset values show as (unset))
  > PATH: moved from PARENT to PARENT         a named element under another parent
  ^ PATH: order of <tag> children changed

each followed by the file and line of the element in A and B. Formatting, attribute order
and the spelling of numbers ("0.10" and ".1") never show; --resolved compares every
attribute as MuJoCo will use it, with default classes applied, so a change to a default
class shows on each element it reaches. --render OUT.png also writes the two models' pictures
side by side (same camera, framing both) and a third panel marking the pixels that differ.

exit status: 0 the models are the same, 1 they differ, 2 a file cannot be read as MJCF."""

_TAG_WIDTH = 160  # characters of an added or removed element's start tag shown
_SHOWN_INSIDE = 20  # elements listed inside an added or removed one (then how many more)


def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument("a", metavar="A.xml", help="the first model")
    parser.add_argument("b", metavar="B.xml", help="the second model")
    parser.add_argument("--resolved", action="store_true",
                        help="compare values with default classes applied")
    parser.add_argument("--render", metavar="OUT.png",
                        help="also write a picture: A and B side by side, and where they differ")
    parser.add_argument("--render-size", type=size, default=(640, 480), metavar="WIDTHxHEIGHT",
                        help="the size of each of --render's three panels (default 640x480)")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    try:
        a = load(args.a)
        b = load(args.b)
    except BadInput as problem:
        error("diff", str(problem))
        return BAD_INPUT
    if args.render is not None and not write_diff_picture(args.render, a, b, args.a, args.b,
                                                          args.render_size):
        return BAD_INPUT
    lines = diff_models(a, b, resolved=args.resolved)
    if not lines:
        return OK
    print(f"--- {shown(args.a)}")
    print(f"+++ {shown(args.b)}")
    for line in lines:
        print(line)
    return FOUND


@dataclass(frozen=True)
class _Line:
    order: tuple[int, int, int]
    text: str


def diff_models(a: Element, b: Element, resolved: bool = False) -> list[str]:
    """The differences between two models (or subtrees), one line each; empty if none."""
    pairs = _align(a, b)
    order_a = {e: i for i, e in enumerate(iter_written(a))}
    order_b = {e: i for i, e in enumerate(iter_written(b))}
    back = {y: x for x, y in pairs.items()}
    lines: list[_Line] = []
    values = _resolved_texts if resolved else _stored_texts
    anchor = 0  # removed elements are listed after what precedes them in A
    for x, position in order_a.items():
        if x in pairs:
            anchor = order_b[pairs[x]]
            continue
        parent = x.parent
        if parent is not None and parent not in pairs:
            continue  # inside a removed element: that one is reported
        lines += [_Line((anchor, 1, order_a[e]), text) for e, text in _subtree("-", x)]
    for y, position in order_b.items():
        counterpart = back.get(y)
        if counterpart is None:
            parent = y.parent
            if parent is None or parent in back:
                lines += [_Line((order_b[e], 0, 0), text) for e, text in _subtree("+", y)]
            continue
        x = counterpart
        found: list[str] = []
        for name, (before, after) in _changes(values(x), values(y)).items():
            found.append(f"~ {y.path}: {name} {_shown_value(before)} -> "
                         f"{_shown_value(after)}")
        if x.parent is not None and y.parent is not None and pairs.get(x.parent) is not y.parent:
            found.append(f"> {y.path}: moved from {x.parent.path} to {y.parent.path}")
        found += [f"^ {y.path}: order of <{tag}> children changed"
                  for tag in _reordered(x, y, pairs)]
        if found:  # where the elements are is looked up only for what is reported
            places = f"  [{where(x)}, {where(y)}]"
            lines += [_Line((position, 0, 0), text + places) for text in found]
    lines.sort(key=lambda line: line.order)
    return [line.text for line in lines]


# ---------------------------------------------------------------------------- alignment


def _align(a: Element, b: Element) -> dict[Element, Element]:
    """Each element of ``a`` paired with its counterpart in ``b``: by tag and name, and
    unnamed ones by their place among the same tag's unnamed children of paired parents."""
    pairs: dict[Element, Element] = {a: b}
    named_b = {key: y for y in iter_written(b) if (key := _name_key(y)) is not None}
    for x in iter_written(a):
        key = _name_key(x)
        if key is not None and key in named_b and x is not a:
            pairs[x] = named_b[key]
    taken = set(pairs.values())
    for x in iter_written(a):  # parents come first: their children are paired by then
        y = pairs.get(x)
        if y is None:
            continue
        for tag, group_a in _unnamed_children(x, pairs).items():
            group_b = [c for c in _unnamed_children(y, {}).get(tag, []) if c not in taken]
            for first, second in _matched(group_a, group_b):
                pairs[first] = second
                taken.add(second)
    return pairs


def _name_key(element: Element) -> tuple[str, str] | None:
    name = tooling.element_name(element)
    return None if name is None else (element.spec.tag, name)


def _unnamed_children(element: Element, pairs: dict[Element, Element]) -> dict[str, list[Element]]:
    groups: dict[str, list[Element]] = {}
    for child in written_children(element):
        if child not in pairs and tooling.element_name(child) is None:
            groups.setdefault(child.spec.tag, []).append(child)
    return groups


# SequenceMatcher compares two sequences in time up to the product of their lengths when
# elements repeat (as unnamed sites often do): used up to this product; longer ones go
# through a shortest edit script with a bounded number of edits (Myers), else by position.
_MATCH_BUDGET = 250_000
_EDIT_BUDGET = 4_000_000  # (length of both) x (edits looked for)


def _matched(group_a: list[Element], group_b: list[Element]) -> Iterable[tuple[Element, Element]]:
    """Pairs of two sequences of elements of one tag: equal runs, and changed elements where
    one sequence has as many in a place as the other (the rest were inserted or deleted).

    The common start and end are paired in one pass; what lies between is compared by
    SequenceMatcher when short, else by a shortest edit script of a bounded number of edits,
    else paired by position: time stays near linear however many siblings there are."""
    signature: Callable[[Element], tuple[tuple[str, str | None], ...]] = (
        lambda e: tuple(_stored_texts(e).items()))
    signs_a = [signature(e) for e in group_a]
    signs_b = [signature(e) for e in group_b]
    start, end_a, end_b = 0, len(signs_a), len(signs_b)
    while start < end_a and start < end_b and signs_a[start] == signs_b[start]:
        start += 1
    while end_a > start and end_b > start and signs_a[end_a - 1] == signs_b[end_b - 1]:
        end_a, end_b = end_a - 1, end_b - 1
    yield from zip(group_a[:start], group_b[:start], strict=True)
    middle_a, middle_b = signs_a[start:end_a], signs_b[start:end_b]
    if len(middle_a) * len(middle_b) <= _MATCH_BUDGET:
        matcher = difflib.SequenceMatcher(None, middle_a, middle_b, autojunk=False)
        indices: list[tuple[int, int]] = []
        for op, i1, i2, j1, j2 in matcher.get_opcodes():
            if op in ("equal", "replace"):
                indices += zip(range(i1, i2), range(j1, j2), strict=False)
    else:
        edits = max(16, _EDIT_BUDGET // (len(middle_a) + len(middle_b)))
        found = _edit_script_pairs(middle_a, middle_b, edits)
        indices = found if found is not None else list(
            zip(range(len(middle_a)), range(len(middle_b)), strict=False))
    yield from ((group_a[start + i], group_b[start + j]) for i, j in indices)
    yield from zip(group_a[end_a:], group_b[end_b:], strict=True)


_Sign = tuple[tuple[str, str | None], ...]


def _edit_script_pairs(a: list[_Sign], b: list[_Sign], max_edits: int) -> list[tuple[int, int]] | None:
    """Index pairs of ``a`` and ``b`` from a shortest edit script (Myers' O((N+M)D)
    algorithm): equal elements, and in each run of deletions and insertions the ones in the
    same place (as SequenceMatcher's "replace"); ``None`` if it takes more than
    ``max_edits`` edits."""
    n, m, offset = len(a), len(b), max_edits + 1
    furthest = [0] * (2 * max_edits + 3)  # on diagonal k (= x - y): the furthest x reached
    trace: list[list[int]] = []
    for d in range(max_edits + 1):
        trace.append(furthest[:])
        for k in range(-d, d + 1, 2):
            if k == -d or (k != d and furthest[k - 1 + offset] < furthest[k + 1 + offset]):
                x = furthest[k + 1 + offset]  # an insertion (down)
            else:
                x = furthest[k - 1 + offset] + 1  # a deletion (right)
            y = x - k
            while x < n and y < m and a[x] == b[y]:
                x, y = x + 1, y + 1
            furthest[k + offset] = x
            if x >= n and y >= m:
                return _pairs_of_script(trace, n, m, offset)
    return None


def _pairs_of_script(trace: list[list[int]], n: int, m: int,
                     offset: int) -> list[tuple[int, int]]:
    """Walk a Myers trace back from the end into index pairs (see :func:`_edit_script_pairs`)."""
    x, y = n, m
    pairs: list[tuple[int, int]] = []
    deleted: list[int] = []
    inserted: list[int] = []

    def flush() -> None:  # a run of edits: the ones in the same place are a change
        pairs.extend(zip(reversed(deleted), reversed(inserted), strict=False))
        deleted.clear()
        inserted.clear()

    for d in range(len(trace) - 1, -1, -1):
        furthest = trace[d]
        k = x - y
        if k == -d or (k != d and furthest[k - 1 + offset] < furthest[k + 1 + offset]):
            previous_k = k + 1
        else:
            previous_k = k - 1
        previous_x = furthest[previous_k + offset]
        previous_y = previous_x - previous_k
        while x > previous_x and y > previous_y:
            flush()
            x, y = x - 1, y - 1
            pairs.append((x, y))
        if d > 0:
            if x == previous_x:
                inserted.append(y - 1)
            else:
                deleted.append(x - 1)
        x, y = previous_x, previous_y
    flush()
    pairs.sort()
    return pairs


def _reordered(x: Element, y: Element, pairs: dict[Element, Element]) -> list[str]:
    """The tags whose children kept under the same parent are in another order."""
    tags: list[str] = []
    mine: dict[str, list[Element]] = {}
    for child in written_children(x):
        counterpart = pairs.get(child)
        if counterpart is not None and counterpart.parent is y:
            mine.setdefault(child.spec.tag, []).append(counterpart)
    for tag, wanted in mine.items():
        kept = set(wanted)
        theirs = [c for c in written_children(y) if c in kept]
        if theirs != wanted:
            tags.append(tag)
    return tags


# ---------------------------------------------------------------------------- values


def _stored_texts(element: Element) -> dict[str, str | None]:
    """The attributes set on ``element``, as canonical text."""
    spec = element.spec
    return {name: stored_text(element, spec.by_name[name])
            for name in sorted(tooling.values(element), key=spec.order.__getitem__)}


def _resolved_texts(element: Element) -> dict[str, str | None]:
    """Every attribute as MuJoCo will use it (defaults applied), as canonical text."""
    spec = element.spec
    try:
        values = resolve_all(element)
    except MjcfError:  # a class that is not defined: compare what is set
        values = {name: tooling.read_value(element, attribute)
                  for name, attribute in spec.attributes.items()}
    return {name: value_text(spec.attributes[name], value) for name, value in values.items()}


def _changes(before: dict[str, str | None],
             after: dict[str, str | None]) -> dict[str, tuple[str | None, str | None]]:
    names = list(before) + [name for name in after if name not in before]
    return {name: (before.get(name), after.get(name)) for name in names
            if before.get(name) != after.get(name)}


def _shown_value(text: str | None) -> str:
    return "(unset)" if text is None else f'"{text}"'


def _subtree(sign: str, top: Element) -> list[tuple[Element, str]]:
    """The lines of an added or removed element: its own, then what is inside it, indented
    by depth (the first ``_SHOWN_INSIDE`` elements, then how many more)."""
    lines = [(top, f"{sign} {top.path}: {_start_tag(top)}  [{where(top)}]")]
    inside = iter(iter_written(top))
    next(inside)  # top itself
    depth = {top: 0}
    more = 0
    for element in inside:
        parent = element.parent
        depth[element] = depth[parent] + 1 if parent is not None and parent in depth else 1
        if len(lines) > _SHOWN_INSIDE:
            more += 1
            continue
        indent = "  " * depth[element]
        lines.append((element, f"{sign} {indent}{element.path}: {_start_tag(element)}"))
    if more:
        last = lines[-1][0]
        plural = "s" if more > 1 else ""
        lines.append((last, f"{sign}   ... and {more} more element{plural} inside {top.path}"))
    return lines


def _start_tag(element: Element) -> str:
    """``<tag a="..." ...>`` with canonical values (shortened); ``/>`` when empty."""
    attributes = "".join(f' {name}="{text}"' for name, text in _stored_texts(element).items()
                         if text is not None)
    tag = f"<{element.spec.tag}{attributes}"
    if len(tag) > _TAG_WIDTH:
        tag = tag[: _TAG_WIDTH - 3] + "..."
    empty = next(itertools.islice(iter_written(element), 1, None), None) is None
    return tag + ("/>" if empty else ">")

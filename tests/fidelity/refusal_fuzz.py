"""False refusals: single-attribute mutants of the corpus models MuJoCo compiles, which MuJoCo
still compiles but typed-mjcf refuses (reading, assigning or ``validate()``).

Each mutant changes one attribute of one element of a corpus file, as a user editing a robot
file would: a keyword from the attribute's set, numbers within its bounds, an array of a legal
length, the attribute removed, or the attribute set in a ``<default>`` class. MuJoCo compiles
each in a worker process (restarted if it crashes or is left unusable) from the file's own
folder; typed-mjcf reads it with the same folder and validates it. Only mutants MuJoCo
compiles count: each that typed-mjcf refuses is a false refusal.

``python -m tests.fidelity.refusal_fuzz [COUNT] [SEED]`` prints the counts and each false
refusal's kind; ``test_refusal_fuzz.py`` runs a small seeded sample (more with
``TYPED_MJCF_FUZZ_MUTANTS``).
"""

from __future__ import annotations

import functools
import random
import sys
import warnings
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

import typed_mjcf as mjcf
from tests.support.compile_worker import MujocoWorker
from tests.support.corpus import CORPUS, corpus_files
from typed_mjcf._core.grammar import AttributeSpec, ElementSpec
from typed_mjcf._model.validate import validate
from typed_mjcf.types import XmlElement


def ours(ident: str, path: Path, xml: str) -> str | None:
    """Why typed-mjcf refuses ``xml`` (read from ``path``'s folder), or None."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            model = mjcf.from_xml_string(xml, base_dir=path.parent,
                                         files=corpus_files(ident, path))
    except mjcf.MjcfError as error:
        return f"load: {' '.join(str(error).split())[:240]}"
    errors = [f for f in validate(model) if f.severity == "error"]
    return f"validate: {errors[0].rule}: {errors[0].message[:200]}" if errors else None


@functools.cache
def _root_spec() -> ElementSpec:
    return mjcf.RootElement.spec


def _rows(root: XmlElement) -> list[tuple[XmlElement, ElementSpec]]:
    """Each element of the document with its grammar row (found from the root down)."""
    found: list[tuple[XmlElement, ElementSpec]] = []
    stack = [(root, _root_spec())]
    while stack:
        node, spec = stack.pop()
        found.append((node, spec))
        for child in node:
            if not isinstance(child.tag, str):
                continue
            entry = spec.children.get(child.tag)
            if entry is not None:
                stack.append((child, entry.cls.spec))
    return found


def _number(rng: random.Random, attribute: AttributeSpec) -> str:
    """A number within the attribute's bounds (a small one: MuJoCo's legal values are)."""
    low, high = -2.0, 2.0
    for op, limit in attribute.bounds:
        if op in (">", ">="):
            low = max(low, limit + (op == ">"))
        else:
            high = min(high, limit - (op == "<"))
    if attribute.kind == "int" or rng.random() < 0.5:
        return str(rng.randint(int(low), max(int(low), int(high))))
    return f"{rng.uniform(low, high):.3g}"


def value(rng: random.Random, attribute: AttributeSpec) -> str | None:
    """A legal-looking text for the attribute, or None for kinds not mutated (names,
    references and files: changing them mostly breaks links, which is no false refusal)."""
    kind = attribute.kind
    if kind in ("keyword", "flags") and attribute.keywords:
        return rng.choice(attribute.keywords)
    if kind in ("int", "real"):
        if not attribute.is_array:
            return _number(rng, attribute)
        high = attribute.hi if attribute.hi is not None else attribute.lo + 3
        count = rng.randint(max(attribute.lo, 1), max(high, 1))
        return " ".join(_number(rng, attribute) for _ in range(count))
    return None


@dataclass(frozen=True)
class Mutant:
    ident: str
    path: Path
    what: str  # "row@attribute: how"
    xml: str


def _mutate(rng: random.Random, root: XmlElement) -> str | None:
    """Change one attribute of one element of ``root`` in place; what was done, or None."""
    rows = [(node, spec) for node, spec in _rows(root) if spec.attributes]
    if not rows:
        return None
    node, spec = rng.choice(rows)
    how = rng.choice(("set", "set", "borrow", "remove", "default"))
    if how == "remove":
        present = [name for name in node.attrib if name in spec.by_name]
        if not present:
            return None
        name = rng.choice(present)
        del node.attrib[name]
        return f"{spec.row}@{name}: removed"
    if how == "default":
        defaults = [(n, s) for n, s in rows if s.row.startswith("default_")]
        if not defaults:
            return None
        node, spec = rng.choice(defaults)
    attribute = rng.choice(list(spec.attributes.values()))
    if how == "borrow":  # a value another corpus file gives the attribute
        texts = written().get(f"{spec.row.removeprefix('default_')}@{attribute.name}")
        text = rng.choice(texts) if texts else None
    else:
        text = value(rng, attribute)
    if text is None:
        return None
    node.set(attribute.name, text)
    return f"{spec.row}@{attribute.name}: {how} {text!r}"


@functools.cache
def written() -> dict[str, list[str]]:
    """Every text the corpus gives each attribute (by "row@name"; a class's under its row),
    for attributes :func:`value` mutates (not names, references, files)."""
    found: dict[str, set[str]] = {}
    for _, path in usable():
        root = etree.fromstring(path.read_bytes(), etree.XMLParser(remove_comments=True))
        for node, spec in _rows(root):
            for name, text in node.attrib.items():
                attribute = spec.by_name.get(str(name))
                if attribute is not None and attribute.kind in ("keyword", "flags", "int",
                                                                "real"):
                    found.setdefault(f"{spec.row.removeprefix('default_')}@{name}",
                                     set()).add(str(text))
    return {key: sorted(texts) for key, texts in found.items()}


@functools.cache
def usable() -> list[tuple[str, Path]]:
    """The corpus files a mutant can be made of (includes are read from their folder)."""
    return list(CORPUS)


def mutants(rng: random.Random, files: list[tuple[str, Path]]) -> Callable[[], Mutant | None]:
    def make() -> Mutant | None:
        ident, path = rng.choice(files)
        root = etree.fromstring(path.read_bytes(), etree.XMLParser(remove_comments=True))
        what = _mutate(rng, root)
        if what is None:
            return None
        return Mutant(ident, path, what, etree.tostring(root, encoding="unicode"))
    return make


@dataclass
class Counts:
    files: set[str] = field(default_factory=set[str])
    mutants: int = 0  # mutants of files MuJoCo compiles
    compiled: int = 0  # of which MuJoCo compiles
    refused: list[tuple[str, Mutant]] = field(default_factory=list[tuple[str, Mutant]])


def run(count: int, seed: int = 0, max_bytes: int | None = None) -> Counts:
    """``count`` mutants of the files MuJoCo compiles (of at most ``max_bytes``: small files
    compile fast), each checked on both sides."""
    rng = random.Random(seed)
    files = [(ident, path) for ident, path in usable()
             if max_bytes is None or path.stat().st_size <= max_bytes]
    compile_error = MujocoWorker()
    counts = Counts()
    good: dict[str, bool] = {}
    make = mutants(rng, files)
    try:
        while counts.mutants < count:
            mutant = make()
            if mutant is None:
                continue
            if mutant.ident not in good:  # the file itself: MuJoCo compiles it?
                good[mutant.ident] = compile_error.compile_text(mutant.path.read_text(),
                                                   mutant.path.parent) is None
            if not good[mutant.ident]:
                continue
            counts.mutants += 1
            counts.files.add(mutant.ident)
            if compile_error.compile_text(mutant.xml, mutant.path.parent) is not None:
                continue
            counts.compiled += 1
            why = ours(mutant.ident, mutant.path, mutant.xml)
            if why is not None:
                counts.refused.append((why, mutant))
    finally:
        compile_error.close()
    return counts


def main() -> None:
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 0
    counts = run(count, seed)
    print(f"{counts.mutants} mutants of {len(counts.files)} files MuJoCo compiles: "
          f"{counts.compiled} compiled by MuJoCo, {len(counts.refused)} false refusals")
    for (why, what), n in Counter((why[:150], m.what) for why, m in counts.refused).most_common():
        print(f"  {n} x {what}\n      {why}")


if __name__ == "__main__":
    main()

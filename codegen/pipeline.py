"""The schema pipeline: grammar file -> normalize -> sync with the installed wheel.

``refresh`` is what ``python -m codegen generate`` runs. With MuJoCo's grammar file it rebuilds
the IR from it; without one (a user with a newer wheel) it syncs the committed IR alone.
"""

from __future__ import annotations

from pathlib import Path

from codegen import ir, passes, wheel
from codegen.facts import Facts, load_facts
from codegen.grammar import parse_grammar
from codegen.reconcile import Report, sync


def build_from_grammar(path: Path, facts: Facts | None = None,
                       installed: wheel.Wheel | None = None) -> tuple[ir.Schema, Report]:
    """Parse ``mjcf.schema`` (symbolic bounds from the wheel's constants), normalize, sync."""
    facts = load_facts() if facts is None else facts
    grammar = parse_grammar(path.read_text(encoding="utf-8"), str(path),
                            wheel.read_constants())
    return sync_schema(passes.normalize(grammar, facts), facts, installed)


def sync_schema(schema: ir.Schema, facts: Facts | None = None,
                installed: wheel.Wheel | None = None, older: bool = False,
                ) -> tuple[ir.Schema, Report]:
    """``schema`` made to agree with the installed wheel, checked like ``normalize`` output
    (``older``: the wheel is an older release than ``schema``'s, see codegen/releases.py)."""
    facts = load_facts() if facts is None else facts
    synced, report = sync(schema, wheel.read_wheel() if installed is None else installed, facts,
                          older)
    passes.finish(synced, facts)
    passes.check(synced)
    return synced, report


def refresh(before: ir.Schema | None, grammar: Path | None, older: bool = False,
            ) -> tuple[ir.Schema, Report]:
    """The new ``schema/mjcf.json``: from ``grammar`` when given, else ``before`` synced
    (``older``: an older release's grammar, for ``schema/releases/``)."""
    if grammar is not None:
        return build_from_grammar(grammar)
    if before is None:
        raise ValueError("no schema/mjcf.json to sync and no --grammar file to build one from")
    return sync_schema(before, older=older)

"""The commands of ``python -m codegen`` (``__main__`` parses the command line and reports
failures; this module does the work)."""

from __future__ import annotations

import sys
from pathlib import Path

from codegen import (
    bindings,
    ir,
    mujoco_stubs,
    pins,
    reference,
    releases,
    render,
    runtime_stubs,
    wheel,
)
from codegen.facts import load_facts
from codegen.pipeline import refresh, sync_schema


def generate(grammar: Path | None, allow_untyped: bool) -> int:
    before = ir.load() if ir.SCHEMA_PATH.exists() else None
    installed = wheel.read_version()
    if (grammar is None and before is not None
            and releases.version_key(installed) < releases.version_key(before.mujoco_version)):
        return generate_older(before, installed)
    schema, report = refresh(before, grammar)
    print(report.format())
    if report.drift_errors:
        for line in report.drift_errors:
            print(f"python -m codegen: error: {line}", file=sys.stderr)
        return 2
    if report.untyped and not allow_untyped:
        print("error: the attributes above cannot be typed precisely; add them to "
              "schema/facts.toml ([[attribute]]) or pass --allow-untyped", file=sys.stderr)
        return 1
    ir.dump(schema)
    for line in pins.update(schema.mujoco_version):  # noxfile.py reads schema/ itself
        print(f"pyproject.toml: {line}")
    if bindings.dump(bindings.read_wheel()):
        print("schema/bindings.json: rewritten from the installed mujoco")
    changed = render.write(render.render(schema))
    print(f"schema/mjcf.json: MuJoCo {schema.mujoco_version}, {len(schema.elements)} rows, "
          f"{sum(len(e.attributes) for e in schema.elements.values())} attributes")
    print("generated/: " + (", ".join(changed) + " rewritten" if changed else "unchanged"))
    write_reference(schema)
    write_runtime_stubs()
    return stubs()


def generate_older(newest: ir.Schema, installed: str) -> int:
    """An older release than schema/mjcf.json's: its grammar (the newest synced with the
    installed wheel) into schema/releases/<version>.json, then generated/ (whose release
    gates it changes). schema/mjcf.json, the bindings and the mujoco stubs stay the newest's:
    the typing surface is one."""
    facts = releases.release_facts(load_facts(), installed)
    path = releases.release_path(installed)
    previous = ir.load(path) if path.exists() else None
    schema, report = sync_schema(releases.with_keywords_of(newest, previous), facts, older=True)
    print(report.format())
    if report.untyped:
        print(f"(MuJoCo {installed} is older than the typing surface, {newest.mujoco_version}: "
              "which attributes, children and keywords it has and how it types them is used; "
              "the attributes above, of rows the typing surface lacks, stay untyped)")
    releases.RELEASES_DIR.mkdir(exist_ok=True)
    ir.dump(schema, path)
    print(f"{path.relative_to(ir.SCHEMA_DIR.parent)}: MuJoCo {installed}, "
          f"{len(schema.elements)} rows, "
          f"{sum(len(e.attributes) for e in schema.elements.values())} attributes")
    changed = render.write(render.render(newest))
    print("generated/: " + (", ".join(changed) + " rewritten" if changed else "unchanged"))
    write_reference(newest)
    return 0


def stubs() -> int:
    changed = mujoco_stubs.write(mujoco_stubs.render())
    print("generated/mujoco-stubs/: "
          + (", ".join(changed) + " rewritten" if changed else "unchanged"))
    return 0


def render_only() -> int:
    schema = ir.load()
    changed = render.write(render.render(schema))
    print("generated/: " + (", ".join(changed) + " rewritten" if changed else "unchanged"))
    write_reference(schema)
    write_runtime_stubs()
    return 0


def write_reference(schema: ir.Schema) -> None:
    """generated/mjcf-reference/: the MJCF reference pages, from schema/."""
    changed = reference.write(reference.render(schema))
    print("generated/mjcf-reference/: "
          + (f"{len(changed)} pages rewritten" if changed else "unchanged"))


def write_runtime_stubs() -> None:
    """generated/runtime-pyi/: the runtime modules' stubs, from src/ (not from schema/)."""
    changed = runtime_stubs.write(runtime_stubs.render())
    print("generated/runtime-pyi/: "
          + (", ".join(changed) + " rewritten" if changed else "unchanged"))


def check() -> int:
    schema = ir.load()
    installed = wheel.read_version()
    if installed != schema.mujoco_version:  # every comparison below would be with another
        print(f"schema/ describes MuJoCo {schema.mujoco_version}, the installed mujoco is "
              f"{installed}: pip install -e '.[dev]' installs the pinned release (or "
              f"`nox -s generate -- --mujoco-version {installed}` moves schema/ and the pins)")
        return 1
    problems = pins.disagreements(pins.PYPROJECT.read_text(encoding="utf-8"), installed)
    if problems:
        print(f"pyproject.toml: {'; '.join(problems)}; `nox -s generate` moves the pins")
        return 1
    files = render.render(schema)
    stale = [name for name, text in sorted(files.items())
             if not (render.GENERATED_DIR / name).exists()
             or (render.GENERATED_DIR / name).read_text(encoding="utf-8") != text]
    if stale:
        print(f"generated/ is out of date: {', '.join(stale)}; run `nox -s generate`")
        return 1
    print("generated/ matches schema/")
    stale_pages = reference.stale(reference.render(schema))
    if stale_pages:
        print(f"generated/mjcf-reference/ is out of date: {', '.join(stale_pages[:5])}"
              f"{' ...' if len(stale_pages) > 5 else ''}; run `python -m codegen render`")
        return 1
    print("generated/mjcf-reference/ matches schema/")
    stale_runtime = runtime_stubs.stale(runtime_stubs.render())
    if stale_runtime:
        print(f"generated/runtime-pyi/ is out of date with src/: {', '.join(stale_runtime)}; "
              "run `python -m codegen render`")
        return 1
    print("generated/runtime-pyi/ matches src/")
    if bindings.dumps(bindings.read_wheel()) != bindings.BINDINGS_PATH.read_text(encoding="utf-8"):
        print("schema/bindings.json is out of date with the installed mujoco; run "
              "`nox -s generate`")
        return 1
    print("schema/bindings.json matches the installed mujoco")
    stale_stubs = mujoco_stubs.stale(mujoco_stubs.render())
    if stale_stubs:
        print(f"generated/mujoco-stubs/ is out of date: {', '.join(stale_stubs)}; "
              "run `python -m codegen stubs`")
        return 1
    print("generated/mujoco-stubs/ matches the installed mujoco")
    return 0

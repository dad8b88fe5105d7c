"""``python -m codegen``: refresh schema/ from MuJoCo's grammar and render generated/.

    python -m codegen generate [--grammar PATH/TO/mjcf.schema] [--allow-untyped]
    python -m codegen render      # schema/ -> generated/ only
    python -m codegen stubs       # the installed mujoco -> generated/mujoco-stubs/
    python -m codegen check       # exit 1 if generated/ differs from a fresh render
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from codegen import ir, mujoco_stubs, render


def _generate(grammar: Path | None, allow_untyped: bool) -> int:
    from codegen.pipeline import refresh

    before = ir.load() if ir.SCHEMA_PATH.exists() else None
    schema, report = refresh(before, grammar)
    print(report.format())
    if report.untyped and not allow_untyped:
        print("error: the attributes above cannot be typed precisely; add them to "
              "schema/facts.toml ([[attribute]]) or pass --allow-untyped", file=sys.stderr)
        return 1
    ir.dump(schema)
    changed = render.write(render.render(schema))
    print(f"schema/mjcf.json: MuJoCo {schema.mujoco_version}, {len(schema.elements)} rows, "
          f"{sum(len(e.attributes) for e in schema.elements.values())} attributes")
    print("generated/: " + (", ".join(changed) + " rewritten" if changed else "unchanged"))
    return _stubs()


def _stubs() -> int:
    changed = mujoco_stubs.write(mujoco_stubs.render())
    print("generated/mujoco-stubs/: "
          + (", ".join(changed) + " rewritten" if changed else "unchanged"))
    return 0


def _render() -> int:
    changed = render.write(render.render(ir.load()))
    print("generated/: " + (", ".join(changed) + " rewritten" if changed else "unchanged"))
    return 0


def _check() -> int:
    files = render.render(ir.load())
    stale = [name for name, text in sorted(files.items())
             if not (render.GENERATED_DIR / name).exists()
             or (render.GENERATED_DIR / name).read_text(encoding="utf-8") != text]
    if stale:
        print(f"generated/ is out of date: {', '.join(stale)}; run `nox -s generate`")
        return 1
    print("generated/ matches schema/")
    stubs = mujoco_stubs.stale(mujoco_stubs.render())
    if stubs:
        print(f"generated/mujoco-stubs/ is out of date: {', '.join(stubs)}; "
              "run `python -m codegen stubs`")
        return 1
    print("generated/mujoco-stubs/ matches the installed mujoco")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m codegen", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    gen = sub.add_parser("generate", help="sync schema/ with the installed mujoco and render")
    gen.add_argument("--grammar", type=Path, help="MuJoCo's src/xml/mjcf.schema to read first")
    gen.add_argument("--allow-untyped", action="store_true",
                     help="write attributes that cannot be typed precisely as strings")
    sub.add_parser("render", help="render generated/ from schema/")
    sub.add_parser("stubs", help="write generated/mujoco-stubs/ from the installed mujoco")
    sub.add_parser("check", help="fail if generated/ differs from a fresh render")
    args = parser.parse_args(argv)
    if args.command == "generate":
        return _generate(args.grammar, args.allow_untyped)
    if args.command == "render":
        return _render()
    if args.command == "stubs":
        return _stubs()
    return _check()


if __name__ == "__main__":
    sys.exit(main())

# Generated from src/typed_mjcf/cli/diff.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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

def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    ...

def run(args: argparse.Namespace) -> int: ...

def diff_models(a: Element, b: Element, resolved: bool = False) -> list[str]:
    """The differences between two models (or subtrees), one line each; empty if none."""
    ...

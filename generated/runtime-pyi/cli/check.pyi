# Generated from src/typed_mjcf/cli/check.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``typed-mjcf check``: read models, run ``validate()`` (and MuJoCo's compiler), report
every finding at the file and line of the element it concerns."""
from __future__ import annotations
import argparse
from dataclasses import asdict, dataclass
from typed_mjcf import CompileLimits, RootElement
from typed_mjcf.io import FileAccess
from typed_mjcf.tooling import (
    DEFAULT_COMPILE_LIMITS,
    Element,
    Problem,
    Refusal,
    WarpMissingError,
    check_compile,
    iter_written,
    vfs_text,
    warp_modules,
    warp_refusals,
)
NAME = "check"
HELP = "validate models against MuJoCo's grammar (and compile them with --compile)"
DESCRIPTION = """\
Read each model (its includes too) and report every mistake in it: misspelt attributes,
values the grammar refuses (a wrong array length, a keyword the tag does not take), names
already taken, children a parent cannot have (each read past, so one file shows them all),
then what MuJoCo's grammar forbids beyond single values: exclusive or required attributes,
required children, references that name nothing (with a did-you-mean), default classes, ...
Each finding is printed as

  FILE:LINE: RULE: ELEMENT PATH: MESSAGE

with "(warning)" after the rule for warnings (legal, but probably not meant), then a summary
line. An attribute MuJoCo's reader ignores (on <frame> and <replicate>, which accept any) is
an ignored-attribute warning. --compile also compiles each model that has no errors with
MuJoCo, first refusing what would make MuJoCo allocate past a limit (--limit NAME=VALUE
raises one, e.g. --limit max_texture_pixels=200000000). --backend warp also lists, element
by element, what the installed MuJoCo Warp refuses (rule "warp"), learnt from Warp itself.

exit status: 0 no errors (warnings allowed, unless --strict), 1 errors found, 2 a file
cannot be read as MJCF at all (not XML, not a model, a missing include: its one-line error
names the file and line; other files are still checked)."""

def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    ...

@dataclass(frozen=True)
class Report:
    """One finding, where it is."""
    file: str
    line: int | None
    rule: str
    severity: str
    path: str
    message: str
    def __str__(self) -> str: ...

def run(args: argparse.Namespace) -> int: ...

def _count(n: int, noun: str) -> str: ...

def check_file(path: str, compile_model: bool = False, files: FileAccess | None = None,
               limits: CompileLimits = DEFAULT_COMPILE_LIMITS, backend: str = "mujoco",
               ) -> list[Report]:
    """The findings for one model file (reading files where ``files`` allows: by default in
    its folder; compiling within ``limits``; ``backend="warp"``: with what MuJoCo Warp
    refuses); raises :class:`BadInput` if it cannot be read."""
    ...

def compile_problem(model: RootElement, file: str,
                    limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> Report | None:
    """MuJoCo's error compiling the model (or reading its files), at the element it names,
    or ``None``."""
    ...

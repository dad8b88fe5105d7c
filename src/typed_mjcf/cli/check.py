"""``typed-mjcf check``: read models, run ``validate()`` (and MuJoCo's compiler), report
every finding at the file and line of the element it concerns."""

from __future__ import annotations

import argparse
import json
import os
import re
import sys
from dataclasses import asdict, dataclass

from lxml import etree

from typed_mjcf._core.errors import IgnoredAttributeWarning, MjcfError, ParseError
from typed_mjcf._core.tree import Element
from typed_mjcf._generated.elements import RootElement
from typed_mjcf._model.resource_limits import DEFAULT_COMPILE_LIMITS, CompileLimits, check_compile
from typed_mjcf._sim.text import vfs_text
from typed_mjcf._text.export import iter_written
from typed_mjcf._text.parse import Problem
from typed_mjcf.cli._common import (
    BAD_INPUT,
    FOUND,
    OK,
    BadInput,
    Progress,
    error,
    load,
    one_line,
    shown,
    source_of,
)
from typed_mjcf.cli._isolated import MujocoCrashed, compile_in_child
from typed_mjcf.cli._limits import add_limit_argument, limits
from typed_mjcf.io import FileAccess

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
raises one, e.g. --limit max_texture_pixels=200000000).

exit status: 0 no errors (warnings allowed, unless --strict), 1 errors found, 2 a file
cannot be read as MJCF at all (not XML, not a model, a missing include: its one-line error
names the file and line; other files are still checked)."""

# MuJoCo ends its messages with the element's line in the text it read: "Element name 'arm',
# id 1, line 22" (compile errors) or "Element 'include', line 7" (XML errors).
_MUJOCO_LINE = re.compile(r"^Element\b.*\bline (\d+)", re.MULTILINE)


def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument("files", nargs="+", metavar="MODEL.xml", help="the models to check")
    parser.add_argument("--compile", action="store_true",
                        help="also compile each model without errors with MuJoCo")
    parser.add_argument("--format", choices=("text", "json"), default="text",
                        help="text (default): one line per finding; json: one JSON document "
                             "with every finding and the summary")
    parser.add_argument("--strict", action="store_true", help="exit 1 on warnings too")
    add_limit_argument(parser, render=False)  # for --compile
    parser.add_argument("--allow-files", action="append", default=[], metavar="FOLDER",
                        help="a folder outside the model's own whose files it may read "
                             "(repeatable; by default only the model's folder)")
    parser.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                        help="show progress on stderr (default: for several files, on a "
                             "terminal)")
    parser.set_defaults(run=run)


@dataclass(frozen=True)
class Report:
    """One finding, where it is."""

    file: str
    line: int | None
    rule: str
    severity: str
    path: str
    message: str

    def __str__(self) -> str:
        where = self.file if self.line is None else f"{self.file}:{self.line}"
        rule = self.rule if self.severity == "error" else f"{self.rule} ({self.severity})"
        return f"{where}: {rule}: {self.path}: {self.message}"


def run(args: argparse.Namespace) -> int:
    files: list[str] = args.files
    as_json = args.format == "json"
    reports: list[Report] = []
    unreadable: list[str] = []
    try:
        access = FileAccess(roots=args.allow_files)
    except MjcfError as problem:  # e.g. --allow-files "": bad input, not a crash
        error(NAME, f"--allow-files: {one_line(str(problem))}")
        return BAD_INPUT
    progress = Progress(len(files), args.progress)
    for file in progress.each(files, "checking"):
        try:
            found = check_file(file, compile_model=args.compile, files=access,
                               limits=limits(args.limit).compile)
        except BadInput as problem:
            progress.clear()
            unreadable.append(str(problem))
            if not as_json:
                error("check", str(problem))
            continue
        reports += found
        if not as_json and found:
            progress.clear()
            for report in found:
                print(report)
    errors = sum(1 for r in reports if r.severity == "error")
    warnings = len(reports) - errors
    summary = _summary(len(files), errors, warnings, len(unreadable))
    if as_json:
        document = {
            "findings": [asdict(report) for report in reports],
            "unreadable": unreadable,
            "summary": {"files": len(files), "errors": errors, "warnings": warnings,
                        "unreadable": len(unreadable)},
        }
        json.dump(document, sys.stdout, indent=2)
        sys.stdout.write("\n")
    else:
        print(summary)
    if unreadable:
        return BAD_INPUT
    return FOUND if errors or (args.strict and warnings) else OK


def _summary(files: int, errors: int, warnings: int, unreadable: int) -> str:
    parts = [_count(errors, "error"), _count(warnings, "warning")]
    if unreadable:
        parts.append(f"{_count(unreadable, 'file')} not readable")
    return f"checked {_count(files, 'file')}: {', '.join(parts)}"


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"


def check_file(path: str, compile_model: bool = False, files: FileAccess | None = None,
               limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> list[Report]:
    """The findings for one model file (reading files where ``files`` allows: by default in
    its folder; compiling within ``limits``); raises :class:`BadInput` if it cannot be
    read."""
    ignored: list[IgnoredAttributeWarning] = []
    problems: list[Problem] = []
    model = load(path, ignored, problems, files)
    reports = [_problem_report(problem, path) for problem in problems]
    reports += [Report(shown(w.source if w.source is not None else path), w.line,
                       "ignored-attribute", "warning", w.path, w.detail) for w in ignored]
    reports += [_report(f.element, f.rule, f.severity, f.path, f.message, path)
                for f in model.validate()]
    if compile_model and not any(r.severity == "error" for r in reports):
        problem = compile_problem(model, path, limits)
        if problem is not None:
            reports.append(problem)
    return reports


def _problem_report(problem: Problem, file: str) -> Report:
    """A mistake the parser read past, at its file and line (its element path in front of
    the message moves to the report's path)."""
    error = problem.error
    message = one_line(error.detail).removeprefix(f"{problem.path}: ")
    return Report(shown(error.source if error.source is not None else file), error.line,
                  problem.rule, "error", problem.path, message)


def _report(element: Element | None, rule: str, severity: str, path: str, message: str,
            file: str) -> Report:
    source, line = source_of(element) if element is not None else (file, None)
    message = one_line(message)
    if source is not None and file and os.path.abspath(file) != source:
        message += f" (in the model {shown(file)} reads)"  # in a file it includes
    return Report(shown(source if source is not None else file), line, rule, severity, path,
                  message)


def compile_problem(model: RootElement, file: str,
                    limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> Report | None:
    """MuJoCo's error compiling the model (or reading its files), at the element it names,
    or ``None``."""
    try:
        check_compile(model, limits)  # what the child would allocate
        xml, collected = vfs_text(model, limits=limits)
    except MjcfError as problem:  # a file the model names cannot (or may not) be read
        message = problem.detail if isinstance(problem, ParseError) else str(problem)
        element = _element_at_path(model, message.split(": ", 1)[0]) or model
        return _report(element, "compile", "error", element.path,
                       message.split(": ", 1)[-1], file)
    try:  # in a child process: a crash in MuJoCo is a finding, not the end of the command
        error = compile_in_child(xml, collected.files)
    except MujocoCrashed as crash:
        return _report(model, "compile", "error", model.path, str(crash), file)
    if error is not None:
        message = error.strip()
        element = model
        match = _MUJOCO_LINE.search(message)
        if match is not None:  # the line is in the text MuJoCo read: point into the file
            element = _element_at_line(model, xml, int(match.group(1))) or model
            message = message[: match.start()].strip() or message
        return _report(element, "compile", "error", element.path,
                       f"MuJoCo: {message.removeprefix('Error: ')}", file)
    return None


def _element_at_path(model: RootElement, path: str) -> Element | None:
    return next((e for e in model.iter_elements() if e.path == path), None)


def _element_at_line(model: RootElement, xml: str, line: int) -> Element | None:
    """The element whose start tag is on ``line`` of ``xml``, the model's export (its
    elements pair in document order with the ones the exporter writes)."""
    try:
        nodes = etree.fromstring(xml.encode("utf-8")).iter()
    except etree.XMLSyntaxError:  # pragma: no cover - the exporter writes well-formed XML
        return None
    for node, element in zip(nodes, iter_written(model), strict=False):
        if node.sourceline == line:
            return element
    return None

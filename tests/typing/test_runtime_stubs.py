"""The runtime's stubs as a user meets them: the wheel's layout, a stub beside each module.

``generated/runtime-pyi/`` (``codegen/runtime_stubs.py``) is what the wheel puts beside the
runtime's modules (pyproject's ``force-include``), so that checkers and editors read the stubs
instead of the implementation. Here the wheel's ``typed_mjcf`` is laid out as pyproject says
(its ``packages`` and ``force-include``) in a fresh environment whose other packages are this
one's, and:

- mypy's ``stubtest`` compares every stub with the module it stands for, at run time
  (names, signatures, defaults, kinds); what it cannot compare, or what differs on purpose, is
  listed in ``UNCHECKED`` or derived from the sources (``if TYPE_CHECKING:`` blocks), each with
  its reason, and an entry that no longer matches anything fails the run;
- user code (the README's blocks, ``examples/``, a module of mistakes, the negative cases of
  ``tests/typing/negative/`` with their six kinds of mistake) gets the same diagnostics from
  ``mypy --strict`` and pyright strict against the wheel's layout as against the source tree,
  with the same configuration (``tests/test_readme.py``'s ``UserCode``: strict mode, the
  ``mujoco`` stubs in ``typings/``, as ``typed-mjcf mujoco-stubs`` puts them; the run
  against the source tree is the one test_readme.py reads, made once per session);
- pyright's language server shows the same hovers and the same public completions on the
  runtime's API either way.

A layout is made by copying files (no build, no network); the build itself is hatch's, whose
``force-include`` of a folder into the package was checked by building the wheel (CHANGELOG).
"""

from __future__ import annotations

import ast
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tomllib
import venv
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import pytest

from codegen import runtime_stubs
from tests.lsp import LanguageServer
from tests.support.typecheck import (
    CHECKERS,
    NEGATIVE_FILES,
    Checker,
    Diagnostic,
)
from tests.support.user_code import CANARY_LINES, UserCode, check_user_code

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = "typed_mjcf"

# What stubtest reports that is no difference between a stub and its module, each with why.
UNCHECKED = {
    # modules, not stubs of the runtime
    r"typed_mjcf\.__main__": "the `python -m typed_mjcf` script: not stubbed, nothing imports it",
    r"typed_mjcf\._generated(\..*)?": "the generated package: elements.pyi and bindings.pyi "
                                        "declare what the runtime installs from the grammar",
    r"typed_mjcf\._mujoco_stubs(\..*)?": "the stubs of `mujoco`, carried as data",
    # the module and its stub say the same; stubtest reads it otherwise
    r"typed_mjcf\.__all__": "`__all__ += _elements.__all__`: mypy does not add a module's "
                            "`__all__` (the statement is the module's own)",
    r"typed_mjcf\.physics\.__all__": "`__all__ += _bindings.__all__`, as above",
    r"typed_mjcf\._dmcompat\.physics\..*": "a module `__getattr__` forwarding to "
                                           "typed_mjcf.physics (dm_control's module name)",
    r"typed_mjcf\._core\.tree\._Slice": "a type alias written as a string (runtime: a str)",
    r"typed_mjcf\._text\.export\.folder_attributes": "functools.cache's wrapper at run time",
    r"typed_mjcf\.(types\.XmlElement|_text\.parse\.XmlNode)\..*": "lxml's `_Element` (types-lxml "
                                                            "against lxml's extension type)",
    r"typed_mjcf\._core\.(rows\.AttributeRow|grammar\.AttributeSpec)\.__slots__":
        "a dataclass's slots: mypy types the synthesized __slots__ as tuple[str, ...], the "
        "runtime's is a tuple of the field names (stubtest compares them as different types)",
    r"typed_mjcf\.physics\.(Data|Model)": "subclasses of MuJoCo's pybind11 classes: "
                                          "pybind11's metaclass",
}


def literal_aliases() -> dict[str, str]:
    """``Kind = Literal[...]`` at module level: stubtest (mypy 2.4.1) reads the runtime's
    ``Literal`` as no Union; the stub's text is the module's."""
    found: dict[str, str] = {}
    for path, module in modules():
        for node in ast.parse(path.read_text(encoding="utf-8")).body:
            if (isinstance(node, ast.Assign) and isinstance(node.value, ast.Subscript)
                    and isinstance(node.value.value, ast.Name)
                    and node.value.value.id == "Literal"):
                for target in node.targets:
                    if isinstance(target, ast.Name):
                        found[re.escape(f"{module}.{target.id}")] = "a Literal alias"
    return found


def type_checking_names() -> dict[str, str]:
    """What ``if TYPE_CHECKING:`` blocks define (no import) and ``if not TYPE_CHECKING:`` /
    ``else:`` blocks define: checkers and the run time see different things on purpose, and
    the stub shows what checkers see."""
    found: dict[str, str] = {}

    def visit(body: list[ast.stmt], prefix: str, in_block: bool) -> None:
        for node in body:
            if isinstance(node, ast.If) and runtime_stubs.is_type_checking(node.test) is not None:
                visit(node.body, prefix, True)
                visit(node.orelse, prefix, True)
            elif isinstance(node, ast.ClassDef):
                if in_block:
                    found[re.escape(f"{prefix}.{node.name}")] = "checkers only / run time only"
                visit(node.body, f"{prefix}.{node.name}", False)
            elif in_block and isinstance(node, ast.FunctionDef | ast.Assign | ast.AnnAssign):
                names = ([node.name] if isinstance(node, ast.FunctionDef)
                         else [t.id for t in ast.walk(node) if isinstance(t, ast.Name)
                               and isinstance(t.ctx, ast.Store)])
                for name in names:
                    found[re.escape(f"{prefix}.{name}")] = "checkers only / run time only"

    for path, module in modules():
        visit(ast.parse(path.read_text(encoding="utf-8")).body, module, False)
    return found


@cache
def modules() -> list[tuple[Path, str]]:
    """The stubbed modules: their source and dotted name."""
    found: list[tuple[Path, str]] = []
    for stub in sorted(runtime_stubs.render()):  # about 2 s of CPU: once
        parts = [PACKAGE, *Path(stub).with_suffix("").parts]
        if parts[-1] == "__init__":
            parts.pop()
        found.append((runtime_stubs.SOURCE_DIR / Path(stub).with_suffix(".py"), ".".join(parts)))
    return found


# ----------------------------------------------------------------------------- the layout


def wheel_files() -> dict[str, Path]:
    """The wheel's files of the package, as pyproject configures hatch: ``{path in the wheel:
    file in the repository}`` (the package folder with its links followed, then the
    ``force-include`` table)."""
    hatch = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))[
        "tool"]["hatch"]["build"]["targets"]["wheel"]
    files: dict[str, Path] = {}
    for package in hatch["packages"]:
        top = ROOT / package
        for folder, _, names in os.walk(top, followlinks=True):
            for name in names:
                if "__pycache__" not in folder:
                    path = Path(folder) / name
                    files[(Path(top.name) / path.relative_to(top)).as_posix()] = path
    for source, target in hatch["force-include"].items():
        source_path = ROOT / source
        if source_path.is_file():
            files[target] = source_path
            continue
        for path in source_path.rglob("*"):
            if path.is_file() and "__pycache__" not in path.parts:
                files[f"{target}/{path.relative_to(source_path).as_posix()}"] = path
    return files


@dataclass(frozen=True)
class Installed:
    """A fresh environment with the wheel's ``typed_mjcf`` and this environment's other
    packages (a ``.pth`` line: the editable install's own ``.pth`` is not read from there)."""

    python: str
    package: Path


@pytest.fixture(scope="module")
def installed(tmp_path_factory: pytest.TempPathFactory) -> Installed:
    home = tmp_path_factory.mktemp("wheel_env")
    venv.create(home, with_pip=False, symlinks=True)
    purelib = Path(sysconfig.get_path("purelib", vars={"base": str(home),
                                                        "platbase": str(home)}))
    for name, source in wheel_files().items():
        (purelib / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source, purelib / name)
    ours = [p for p in sys.path if p.endswith("site-packages") and Path(p).is_dir()]
    (purelib / "_this_environment.pth").write_text("\n".join(ours) + "\n", encoding="utf-8")
    python = str(home / "bin" / "python")
    where = subprocess.run([python, "-c", "import typed_mjcf; print(typed_mjcf.__file__)"],
                           capture_output=True, text=True, check=True).stdout.strip()
    assert Path(where) == purelib / PACKAGE / "__init__.py", where
    return Installed(python, purelib / PACKAGE)


def test_the_wheel_has_a_stub_beside_each_runtime_module() -> None:
    files = wheel_files()
    for _, module in modules():
        name = module.replace(".", "/")
        stub = f"{name}/__init__.pyi" if f"{name}/__init__.py" in files else f"{name}.pyi"
        assert stub in files, f"the wheel has no {stub}"
        assert files[stub].is_relative_to(runtime_stubs.STUBS_DIR)
    # ... and the repository's source tree none: its checks read the implementation
    assert not list(runtime_stubs.SOURCE_DIR.glob("*.pyi"))


# ----------------------------------------------------------------------------- stubtest


def test_the_stubs_match_the_implementation(installed: Installed, tmp_path: Path) -> None:
    kept_by_hand = {**UNCHECKED, **literal_aliases()}
    allow = {**type_checking_names(), **kept_by_hand}
    allowlist = tmp_path / "allowlist.txt"
    allowlist.write_text("".join(f"{pattern}  # {why}\n" for pattern, why in allow.items()),
                         encoding="utf-8")
    typings = tmp_path / "typings"
    shutil.copytree(ROOT / "generated" / "mujoco-stubs", typings / "mujoco")
    done = subprocess.run(
        [installed.python, "-m", "mypy.stubtest", PACKAGE, "--allowlist", str(allowlist),
         "--mypy-config-file", str(write(tmp_path / "mypy.ini", "[mypy]\n"))],
        cwd=tmp_path, capture_output=True, text=True, check=False,
        env={**os.environ, "MYPYPATH": str(typings)})
    said = done.stdout + done.stderr
    assert re.search(r"checked \d+ modules", said), said[-20000:]
    errors = [line for line in said.splitlines() if line.startswith("error")]
    assert not errors, said[-20000:]
    # an entry kept by hand that matches nothing is stale (a derived one may match nothing:
    # stubtest leaves some names out of its comparison, dunders it finds inherited)
    unused = {line.partition("unused allowlist entry ")[2]
              for line in said.splitlines() if "unused allowlist entry" in line}
    assert not unused & set(kept_by_hand), said[-20000:]


def write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


# ----------------------------------------------------------------------------- user code


@pytest.fixture(scope="module")
def reports(installed: Installed, user_code: UserCode,
            user_code_reports: dict[Checker, list[Diagnostic]],
            tmp_path_factory: pytest.TempPathFactory,
            ) -> Mapping[str, dict[Checker, list[Diagnostic]]]:
    """The user's project checked against the wheel's layout, and (tests/conftest.py's run,
    which test_readme.py reads too) against the source tree."""
    return {"wheel": check_user_code(user_code, installed.python,
                                     tmp_path_factory.mktemp("mypy_cache")),
            "source": user_code_reports}


@pytest.mark.parametrize("checker", CHECKERS)
def test_user_code_checks_the_same_against_the_wheel(
        checker: Checker, user_code: UserCode,
        reports: Mapping[str, dict[Checker, list[Diagnostic]]]) -> None:
    wheel, source = (sorted(reports[layout][checker]) for layout in ("wheel", "source"))
    only_wheel = [d for d in wheel if d not in source]
    only_source = [d for d in source if d not in wheel]
    assert not only_wheel and not only_source, (
        f"{checker}: against the wheel only:\n" + "\n".join(map(str, only_wheel))
        + "\nagainst the source tree only:\n" + "\n".join(map(str, only_source)))
    # what makes the comparison able to fail: the mistakes are seen, in every negative case
    assert sorted({d.line for d in wheel if d.file == user_code.canary}) == CANARY_LINES
    for path in NEGATIVE_FILES:
        assert any(d.file.name == path.name for d in wheel), f"{checker}: nothing in {path.name}"


# ----------------------------------------------------------------------------- the editor

EDITOR_SOURCE = """\
import typed_mjcf as mjcf

model = mjcf.from_path("robot.xml")
xml = model.to_xml_string(precision=6)
found = model.find("joint", "hip")
joints = model.find_all("joint")
scope = model.namescope
model.
"""
HOVERS = ["from_path", "to_xml_string", "find", "find_all", "namescope", "precision"]


def editor_view(python: str, folder: Path) -> tuple[list[str], list[str]]:
    """Hovers on ``HOVERS`` and the public completions after ``model.``."""
    server = LanguageServer(folder, 120.0, python)
    try:
        lines = EDITOR_SOURCE.splitlines()
        uri = server.open(folder / "probe.py", EDITOR_SOURCE)
        hovers: list[str] = []
        for word in HOVERS:
            line = next(n for n, text in enumerate(lines) if word in text)
            hovers.append(server.hover(uri, line, lines[line].index(word) + 1))
        completions = server.completion(uri, len(lines) - 1, len("model."))
        labels = sorted(str(item["label"]) for item in completions
                        if not str(item["label"]).startswith("_"))
        return hovers, labels
    finally:
        server.close()


def test_the_editor_shows_the_same(installed: Installed, user_code: UserCode) -> None:
    wheel_hovers, wheel_labels = editor_view(installed.python, user_code.folder)
    source_hovers, source_labels = editor_view(sys.executable, user_code.folder)
    assert wheel_labels == source_labels
    assert {"to_xml_string", "find", "find_all", "compile", "worldbody"} <= set(wheel_labels)
    for word, wheel, source in zip(HOVERS, wheel_hovers, source_hovers, strict=True):
        assert wheel == source, f"hover on {word}:\nwheel: {wheel}\nsource: {source}"
        assert wheel, f"no hover on {word}"

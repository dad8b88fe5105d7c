"""Models that crash MuJoCo (SIGSEGV inside ``MjModel.from_xml_string``) or make it raise a
foreign exception: refused by ``validate()`` where the grammar (with its hand-kept facts)
tells, and reported by ``typed-mjcf check --compile``, which compiles in a child process,
where it does not. MuJoCo itself only ever runs here in a child process."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from typed_mjcf.cli import main

from ..runtime.test_io import box_stl

_GRID = 'type="grid" count="2 2 1" spacing="1 1 1" dim="2" name="f"'
# Each crashed MuJoCo 4.0.0 (measured: the child is killed by SIGSEGV), or made it raise
# RuntimeError ("Caught an unknown exception!"), or refuse the model at compile time.
REFUSED = {
    "mesh-file-plugin": ('<asset><mesh file="box.stl"><plugin/></mesh></asset>', "oneof"),
    "flexcomp-plugin": (f"<worldbody><flexcomp {_GRID}><plugin/></flexcomp></worldbody>",
                        "oneof"),
    "flexcomp-plugin-config": ((f'<worldbody><flexcomp {_GRID}><plugin><config key="a" '
                                'value="b"/></plugin></flexcomp></worldbody>'), "oneof"),
    "body-plugin": ("<worldbody><body><plugin/></body></worldbody>", "oneof"),
    "sensor-plugin": ("<sensor><plugin/></sensor>", "oneof"),
    "model-asset-without-file": ('<asset><model name="x"/></asset>', "required-attribute"),
    "extension-plugin": ("<extension><plugin/></extension>", "required-attribute"),
}
_CHILD = """
import sys, mujoco
try:
    mujoco.MjModel.from_xml_string(sys.stdin.read(), {"box.stl": open(sys.argv[1], "rb").read()})
except Exception as error:
    print(type(error).__name__, str(error).splitlines()[0])
else:
    print("compiled")
"""


def _mujoco(xml: str, stl: Path) -> str:
    """What MuJoCo does with ``xml``, in a child process: a signal's name, or its answer."""
    done = subprocess.run([sys.executable, "-c", _CHILD, str(stl)], input=xml, text=True,
                          capture_output=True, timeout=120, check=False)
    return f"signal {-done.returncode}" if done.returncode < 0 else done.stdout.strip()


@pytest.fixture
def stl(tmp_path: Path) -> Path:
    path = tmp_path / "box.stl"
    path.write_bytes(box_stl(0.1))
    return path


@pytest.mark.parametrize("case", sorted(REFUSED))
def test_what_mujoco_cannot_compile_is_refused_by_validate(case: str, stl: Path) -> None:
    body, rule = REFUSED[case]
    xml = f"<mujoco>{body}</mujoco>"
    assert _mujoco(xml, stl) != "compiled"  # still true of the installed MuJoCo
    model = mjcf.from_xml_string(xml, base_dir=stl.parent)
    assert [f.rule for f in model.validate() if f.severity == "error"] == [rule]
    with pytest.raises(mjcf.ValidationError, match=rule):
        model.compile()  # MuJoCo never sees it


def test_the_crashes_are_crashes(stl: Path) -> None:
    """The cases above that kill MuJoCo (so the refusal matters: nothing could catch it)."""
    for case in ("mesh-file-plugin", "flexcomp-plugin"):
        assert _mujoco(f"<mujoco>{REFUSED[case][0]}</mujoco>", stl) == "signal 11", case


# A crash the grammar cannot tell: a mesh read from a file, with a plugin named but no
# instance (with instance= it compiles and the plugin is ignored).
CRASH = ('<mujoco><asset><mesh file="box.stl"><plugin plugin="mujoco.sdf.torus"/></mesh>'
         '</asset></mujoco>')


def test_check_compile_reports_a_crash_as_a_finding(stl: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    assert _mujoco(CRASH, stl) == "signal 11"
    model = stl.parent / "crash.xml"
    model.write_text(CRASH)
    fine = stl.parent / "fine.xml"
    fine.write_text('<mujoco><asset><mesh file="box.stl"/></asset></mujoco>')
    assert main(["check", "--compile", str(model), str(fine)]) == 1
    assert capsys.readouterr().out.splitlines() == [
        f"{model}:1: compile: <root>: MuJoCo crashed compiling the model: signal SIGSEGV",
        "checked 2 files: 1 error, 0 warnings"]


def test_compile_raises_the_librarys_error_for_mujocos_runtime_error() -> None:
    """``compile()`` itself (no validation in the way): MuJoCo's RuntimeError is a
    CompileError."""
    code = textwrap.dedent("""
        import typed_mjcf as mjcf
        from typed_mjcf import _bridge, _validate
        model = mjcf.from_xml_string('<mujoco><asset><model name="x"/></asset></mujoco>')
        _bridge.ensure_valid = lambda model: None  # as if validate() let it through
        try:
            model.compile()
        except mjcf.CompileError as error:
            print("CompileError", error)
    """)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120, check=False)
    assert done.stdout.startswith("CompileError MuJoCo could not compile the model: "), done

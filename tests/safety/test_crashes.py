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
from tests.support.meshes import box_stl
from typed_mjcf.cli import main
from typed_mjcf.cli.check import compile_problem

_GRID = 'type="grid" count="2 2 1" spacing="1 1 1" dim="2" name="f"'
# Each crashed MuJoCo 4.0.0 (measured: the child is killed by SIGSEGV), or made it raise
# RuntimeError ("Caught an unknown exception!"), or refuse the model at compile time.
# A file <mesh> whose <plugin> has no instance= crashes MuJoCo whatever else the plugin says,
# a <flexcomp> whose <plugin> says nothing too (schema/facts.toml's child_needs):
# "child-needs", besides "oneof" when the plugin says nothing.
_TORUS = '<extension><plugin plugin="mujoco.sdf.torus"><instance name="t"/></plugin></extension>'
REFUSED: dict[str, tuple[str, tuple[str, ...]]] = {
    "mesh-file-plugin": ('<asset><mesh file="box.stl"><plugin/></mesh></asset>',
                         ("child-needs", "oneof")),
    "mesh-file-plugin-named": (('<asset><mesh file="box.stl"><plugin '
                                'plugin="mujoco.sdf.torus"/></mesh></asset>'), ("child-needs",)),
    "mesh-file-plugin-declared": ((_TORUS + '<asset><mesh file="box.stl"><plugin '
                                   'plugin="mujoco.sdf.torus"/></mesh></asset>'),
                                  ("child-needs",)),
    "mesh-file-plugin-config": (('<asset><mesh file="box.stl"><plugin plugin="x"><config '
                                 'key="a" value="1"/></plugin></mesh></asset>'), ("child-needs",)),
    "flexcomp-plugin": (f"<worldbody><flexcomp {_GRID}><plugin/></flexcomp></worldbody>",
                        ("child-needs", "oneof")),
    "flexcomp-plugin-config": ((f'<worldbody><flexcomp {_GRID}><plugin><config key="a" '
                                'value="b"/></plugin></flexcomp></worldbody>'),
                               ("child-needs", "oneof")),
    "body-plugin": ("<worldbody><body><plugin/></body></worldbody>", ("oneof",)),
    "sensor-plugin": ("<sensor><plugin/></sensor>", ("oneof",)),
    "model-asset-without-file": ('<asset><model name="x"/></asset>', ("required-attribute",)),
    "extension-plugin": ("<extension><plugin/></extension>", ("required-attribute",)),
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
    body, rules = REFUSED[case]
    xml = f"<mujoco>{body}</mujoco>"
    assert _mujoco(xml, stl) != "compiled"  # still true of the installed MuJoCo
    model = mjcf.from_xml_string(xml, base_dir=stl.parent)
    assert sorted(f.rule for f in model.validate() if f.severity == "error") == list(rules)
    with pytest.raises(mjcf.ValidationError, match=rules[0]):
        model.compile()  # MuJoCo never sees it


def test_the_crashes_are_crashes(stl: Path) -> None:
    """The cases above that kill MuJoCo (so the refusal matters: nothing could catch it)."""
    for case in ("mesh-file-plugin", "mesh-file-plugin-named", "mesh-file-plugin-declared",
                 "mesh-file-plugin-config", "flexcomp-plugin", "flexcomp-plugin-config"):
        assert _mujoco(f"<mujoco>{REFUSED[case][0]}</mujoco>", stl) == "signal 11", case


# Plugins MuJoCo compiles or refuses with an error: not refused for crashing (a file mesh
# with instance=, a mesh without a file, the other plugin hosts with plugin= alone).
NOT_CRASHES = {
    "mesh-file-instance": _TORUS + ('<asset><mesh file="box.stl"><plugin instance="t"/></mesh>'
                                    '</asset>'),
    "mesh-vertices-plugin": _TORUS + ('<asset><mesh name="m" vertex="0 0 0 1 0 0 0 1 0 0 0 1">'
                                      '<plugin plugin="mujoco.sdf.torus"/></mesh></asset>'),
    "geom-plugin": _TORUS + ('<worldbody><geom size="1"><plugin plugin="mujoco.sdf.torus"/>'
                             '</geom></worldbody>'),
    "body-plugin-named": ('<worldbody><body><geom size="1"/><plugin plugin="x"/></body>'
                          '</worldbody>'),
    "flexcomp-plugin-named": f'<worldbody><flexcomp {_GRID}><plugin plugin="x"/></flexcomp></worldbody>',
    "sensor-plugin-named": ('<worldbody><site name="s"/></worldbody><sensor><plugin objtype="site" '
                            'objname="s" plugin="x"/></sensor>'),
}


@pytest.mark.parametrize("case", sorted(NOT_CRASHES))
def test_plugins_mujoco_answers_are_not_refused_for_crashing(case: str, stl: Path) -> None:
    xml = f"<mujoco>{NOT_CRASHES[case]}</mujoco>"
    assert not _mujoco(xml, stl).startswith("signal")
    model = mjcf.from_xml_string(xml, base_dir=stl.parent)
    assert [f.rule for f in model.validate() if f.rule == "child-needs"] == []


def test_the_refusal_names_the_plugin_and_what_it_needs(stl: Path) -> None:
    model = mjcf.RootElement()
    mesh = model.asset.add_mesh(name="m", file=str(stl))
    plugin = mesh.add_plugin(plugin="mujoco.sdf.torus")
    [finding] = model.validate()
    assert (finding.path, finding.rule, finding.severity) == (
        "asset/mesh[m]/plugin[0]", "child-needs", "error")
    assert finding.message == ("a <plugin> in a <mesh> with file= needs instance=: without, "
                               "MuJoCo crashes the process compiling it (SIGSEGV)")
    with pytest.raises(mjcf.ValidationError, match="needs instance="):
        model.compile()
    model.extension.add_plugin(plugin="mujoco.sdf.torus").add_instance(name="t")
    plugin.instance = "t"
    del plugin.plugin
    assert model.validate() == [] and model.compile().nmesh == 1


def test_writing_a_composed_model_with_keyframes_refuses_a_crash(stl: Path) -> None:
    """Combining attached models' keyframes compiles the composed model in this process,
    without validating it: what would crash MuJoCo is refused there too."""
    arm = mjcf.RootElement(model="arm")
    arm.asset.add_mesh(name="m", file=str(stl)).add_plugin(plugin="mujoco.sdf.torus")
    arm.worldbody.add_body(name="b").add_joint(name="j")
    arm.keyframe.add_key(name="home", qpos=(0.5,))
    world = mjcf.RootElement(model="world")
    world.worldbody.add_site(name="s").attach(arm)
    with pytest.raises(mjcf.ValidationError, match=r"arm/asset/mesh\[m\]/plugin\[0\].*needs "
                                                   r"instance="):
        world.to_xml_string()


# A crash the grammar cannot tell, as the child process of `check --compile` sees it: the
# case above, with validate() out of the way.
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
        (f"{model}:1: child-needs: asset/mesh[0]/plugin[0]: a <plugin> in a <mesh> with "
         "file= needs instance=: without, MuJoCo crashes the process compiling it (SIGSEGV)"),
        "checked 2 files: 1 error, 0 warnings"]
    report = compile_problem(mjcf.from_path(str(model)), str(model))
    assert report is not None
    assert report.message == "MuJoCo crashed compiling the model: signal SIGSEGV"


def test_compile_raises_the_librarys_error_for_mujocos_runtime_error() -> None:
    """``compile()`` itself (no validation in the way): MuJoCo's RuntimeError is a
    CompileError."""
    code = textwrap.dedent("""
        import typed_mjcf as mjcf
        from typed_mjcf._model import validate as _validate
        from typed_mjcf._sim import bridge as _bridge
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

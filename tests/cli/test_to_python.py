"""``typed-mjcf to-python``: the code rebuilds every corpus model exactly, reads as a person
would write it, and is laid out as black and ruff lay it out."""

from __future__ import annotations

import math
import runpy
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support.compare import file_differences, model_differences
from tests.support.corpus import SEPARATORS, compiled, corpus_params, module_name
from typed_mjcf.cli import _pycode, main
from typed_mjcf.cli._common import BadInput
from typed_mjcf.cli.diff import diff_models
from typed_mjcf.cli.to_python import to_python


def _build(code: str, file: Path) -> mjcf.RootElement:
    file.write_text(code, encoding="utf-8")
    built = runpy.run_path(str(file))["build"]()
    assert isinstance(built, mjcf.RootElement)
    return built


@pytest.mark.parametrize(("ident", "path"), corpus_params())
def test_the_code_rebuilds_the_model(ident: str, path: Path, tmp_path: Path) -> None:
    expected = compiled(ident, path)
    model = mjcf.from_path(path)
    if ident == SEPARATORS:
        with pytest.raises(BadInput, match=r"model_with_separators.xml:14: <geom> name "
                                           r"'left/cube' holds '/'"):
            to_python(model, str(tmp_path))
        return
    code = to_python(model, str(tmp_path))
    built = _build(code, tmp_path / module_name(ident))
    actual = built.compile()
    assert model_differences(expected, actual) == []
    assert file_differences(expected, str(path), actual, built.get_assets()) == []
    too_long = [line for line in code.splitlines() if len(line) > _pycode.WIDTH]
    assert too_long == []
    # what the README promises: `typed-mjcf diff original.xml rebuilt.xml` shows nothing
    rebuilt = tmp_path / "rebuilt.xml"
    rebuilt.write_text(built.to_xml_string(), encoding="utf-8")
    assert diff_models(model, built) == []
    assert diff_models(model, mjcf.from_path(rebuilt)) == []


CARTPOLE = """\
<mujoco model="cart-pole">
  <include file="parts.xml"/>
  <option timestep="0.01" integrator="RK4"><flag contact="disable"/></option>
  <default>
    <default class="pole">
      <joint type="hinge" axis="0 1 0" damping="2e-6"/>
      <geom type="capsule" fromto="0 0 0 0 0 1" size="0.045" material="self" mass=".1"/>
    </default>
  </default>
  <worldbody>
    <body name="cart" pos="0 0 1">
      <joint name="slider" type="slide" limited="true" range="-1.8 1.8"/>
      <geom name="cart" type="box" size="0.2 0.15 0.1" rgba="0.1 0.2 0.3 1"/>
      <body name="pole" childclass="pole">
        <joint name="hinge"/>
        <geom name="pole"/>
      </body>
    </body>
  </worldbody>
  <actuator>
    <motor name="slide" joint="slider" gear="10"/>
    <motor name="swing" joint="hinge"/>
  </actuator>
</mujoco>
"""
PARTS = """\
<mujoco>
  <asset>
    <material name="self" rgba=".7 .5 .3 1"/>
    <mesh name="box" file="box.obj"/>
  </asset>
</mujoco>
"""


def _cartpole(folder: Path) -> Path:
    folder.mkdir(exist_ok=True)
    (folder / "parts.xml").write_text(PARTS, encoding="utf-8")
    (folder / "box.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                    "f 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n", encoding="utf-8")
    main_file = folder / "cartpole.xml"
    main_file.write_text(CARTPOLE, encoding="utf-8")
    return main_file


EXPECTED = '''\
"""The MJCF model "cart-pole" (cartpole.xml) as typed-mjcf code.

Written by ``typed-mjcf to-python``; running it prints the model's MJCF.
"""

from pathlib import Path

import typed_mjcf as mjcf

HERE = Path(__file__).parent
# the folder of cartpole.xml: its files are found from there
MODEL_DIR = HERE / "model"


def build() -> mjcf.RootElement:
    """The model, built as cartpole.xml describes it."""
    model = mjcf.RootElement(model="cart-pole", model_dir=str(MODEL_DIR))

    add_parts(model)

    option = model.add_option(timestep=0.01, integrator="RK4")
    option.add_flag(contact="disable")

    pole_class = model.default.add_default(class_="pole")
    pole_class.add_joint(type="hinge", axis=(0, 1, 0), damping=2e-6)
    pole_class.add_geom(
        type="capsule", size=0.045, material="self", mass=0.1, fromto=(0, 0, 0, 0, 0, 1)
    )

    cart = model.worldbody.add_body(name="cart", pos=(0, 0, 1))
    slider = cart.add_joint(name="slider", type="slide", limited=True, range=(-1.8, 1.8))
    cart.add_geom(name="cart", type="box", size=(0.2, 0.15, 0.1), rgba=(0.1, 0.2, 0.3, 1))

    pole = cart.add_body(name="pole", childclass=pole_class)
    hinge = pole.add_joint(name="hinge")
    pole.add_geom(name="pole")

    actuator = model.actuator
    actuator.add_motor(name="slide", gear=10, joint=slider)
    actuator.add_motor(name="swing", joint=hinge)

    return model


def add_parts(model: mjcf.RootElement) -> None:
    """The elements parts.xml adds."""
    asset = model.asset
    asset.add_material(name="self", rgba=(0.7, 0.5, 0.3, 1))
    asset.add_mesh(name="box", file="box.obj")


if __name__ == "__main__":
    print(build().to_xml_string())
'''


def test_the_code_reads_like_hand_written_code(tmp_path: Path) -> None:
    """One function per file, the included one called where it was included; elements in
    reading order, attributes in MJCF's order, values as typed (the float32 rgba too);
    variables only for what later code uses, references to them as variables (the actuators'
    joints, the childclass), by name otherwise (the material, from another function); once-only
    sections through their properties, bound to a variable when used twice; files relative to
    the module."""
    source = _cartpole(tmp_path / "model")
    assert to_python(mjcf.from_path(source), str(tmp_path)) == EXPECTED


def test_running_the_module_prints_the_model(tmp_path: Path) -> None:
    source = _cartpole(tmp_path / "model")
    module = tmp_path / "cartpole.py"
    assert main(["to-python", str(source), "-o", str(module)]) == 0
    printed = subprocess.run([sys.executable, str(module)], capture_output=True, text=True,
                             check=True, cwd="/").stdout
    assert 'file="box.obj"' in printed  # as the source names it ...
    again = mjcf.from_xml_string(printed, model_dir=source.parent)  # ... from its folder
    assert again.find("joint", "slider") is not None
    assert again.compile().nmesh == 1  # the mesh was found from another folder


def test_without_output_file_the_code_goes_to_stdout(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    source = _cartpole(tmp_path / "model")
    assert main(["to-python", str(source)]) == 0
    assert "def build() -> mjcf.RootElement:" in capsys.readouterr().out


def test_variables_do_not_clash(tmp_path: Path) -> None:
    source = tmp_path / "m.xml"
    source.write_text(
        '<mujoco><worldbody><body name="arm"><site name="arm"/><joint name="Arm"/>'
        '<geom name="list" size="1"/><body name="1st"/></body><body name="class"><geom size="1"/>'
        '</body></worldbody><sensor><framepos objtype="site" objname="arm"/>'
        '<jointpos joint="Arm"/><framepos objtype="body" objname="1st"/></sensor></mujoco>',
        encoding="utf-8")
    code = to_python(mjcf.from_path(source), str(tmp_path))
    assert '    arm = worldbody.add_body(name="arm")' in code
    assert '    arm_site = arm.add_site(name="arm")' in code
    assert '    arm_joint = arm.add_joint(name="Arm")' in code
    assert '    body_1st = arm.add_body(name="1st")' in code
    assert '    class_ = worldbody.add_body(name="class")' in code
    assert 'sensor.add_framepos(objtype="site", objname=arm_site)' in code
    model = _build(code, tmp_path / "m.py")
    assert model.to_xml_string() == mjcf.from_path(source).to_xml_string()


def test_numbers_are_written_as_typed() -> None:
    assert [_pycode.number(x) for x in (1.0, 0.1, 2e-6, -0.0, 0.0, 1e20, -1.5, 123.0)] == [
        "1", "0.1", "2e-6", "-0.0", "0", "1e20", "-1.5", "123"]
    assert [_pycode.number(x) for x in (math.inf, -math.inf, math.nan)] == [
        "math.inf", "-math.inf", "math.nan"]
    assert _pycode.string('say "hi"') == "'say \"hi\"'"
    assert _pycode.string("it's") == '"it\'s"'
    assert _pycode.identifier("Left Arm/2", "body") == "left_arm_2"
    assert _pycode.identifier("2nd", "geom") == "geom_2nd"
    assert _pycode.identifier("import", "body") == "import_"
    assert _pycode.identifier("***", "site") == "site"


def test_float32_values_round_as_mujoco_reads_them(tmp_path: Path) -> None:
    # The decimal is just above a float32 tie, but its nearest double is exactly the tie, so
    # a double rounded to float32 lands on the other side (half to even): the code must give
    # the float32 that the text reads as.
    tie = float(np.float32(1)) + 2.0**-24  # halfway between 1 and the next float32
    text = "1.000000059604644775390625000000000001"  # a hair above it
    assert float(text) == tie and np.float32(tie) == np.float32(1)
    source = tmp_path / "m.xml"
    source.write_text(f'<mujoco><worldbody><geom size="1" rgba="{text} 0 0 1"/></worldbody>'
                      "</mujoco>", encoding="utf-8")
    model = mjcf.from_path(source)
    code = to_python(model, str(tmp_path))
    built = _build(code, tmp_path / "m.py")
    rgba = built.worldbody.geom[0].rgba
    assert rgba is not None and rgba[0] == np.nextafter(np.float32(1), np.float32(2))
    assert rgba[0] == model.worldbody.geom[0].rgba[0]  # type: ignore[index]


def test_bulk_numbers_are_filled_and_kept_from_formatters(tmp_path: Path) -> None:
    vertex = " ".join(str(i % 7 * 0.125) for i in range(60))
    source = tmp_path / "m.xml"
    source.write_text(f'<mujoco><asset><mesh name="m" vertex="{vertex}"/></asset></mujoco>',
                      encoding="utf-8")
    code = to_python(mjcf.from_path(source), str(tmp_path))
    lines = code.splitlines()
    start = lines.index("    # fmt: off")
    assert lines[start + 1:start + 4] == ["    model.asset.add_mesh(", '        name="m",',
                                          "        vertex=("]
    assert lines[start + 4].startswith("            0, 0.125, 0.25, 0.375,")
    assert "    # fmt: on" in lines
    assert all(len(line) <= _pycode.WIDTH for line in lines)


def test_a_model_that_cannot_be_built_in_python_is_bad_input(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    source = tmp_path / "m.xml"
    source.write_text('<mujoco>\n<worldbody>\n<geom name="a/b" size="1"/>\n</worldbody>\n'
                      "</mujoco>\n", encoding="utf-8")
    assert main(["to-python", str(source)]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err.count("\n") == 1
    assert "m.xml:3: <geom> name 'a/b' holds '/'" in captured.err

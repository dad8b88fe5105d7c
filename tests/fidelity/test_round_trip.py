"""Round trip: parsing then exporting keeps everything but comments.

Element order, names and every attribute survive; floats read back bit for bit (-0.0 and
subnormals included); keywords and flags as MuJoCo spells them (which MuJoCo alone reads in files); given in
Python in any case or order, they are stored that way.
"""

from __future__ import annotations

import struct

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support.compare import model_differences
from typed_mjcf import Element
from typed_mjcf._model.validate import validate
from typed_mjcf._releases.facts import UNDERFLOWING_NUMBERS, has

# The smallest positive double the installed MuJoCo reads: a subnormal from 4.0.0 on; the
# older releases refuse numbers that underflow (schema/releases/behaviour.toml; their refusal is
# tests/runtime/test_release_facts.py's), and read the smallest normal number.
TINY = 5e-324 if has(UNDERFLOWING_NUMBERS) else 2.2250738585072014e-308

DOCUMENT = f"""<?xml version="1.0"?>
<!-- a comment before the root -->
<mujoco model="every-value">
  <!-- comments are not kept -->
  <compiler angle="radian" autolimits="true" eulerseq="XyZ"/>
  <option timestep="0.001" gravity="0 -0 -9.81" iterations="2147483647"
          actuatorgroupdisable="0 5 30" integrator="implicitfast">
    <flag contact="disable" energy="enable"/>
  </option>
  <default>
    <default class="limb">
      <geom rgba="0.1 0.2 0.3 0.33333334" friction="1e-300 {TINY!r} 1.7976931348623157e308"/>
      <default class="finger">
        <joint damping="0.1" range="-3.141592653589793 3.141592653589793"/>
      </default>
    </default>
  </default>
  <asset>
    <material name="steel" rgba="1 1 1 1" texrepeat="2.5 -0"/>
  </asset>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 0.05"/>
    <body name="upper" pos="0.1 0.3333333333333333 -0" quat="1 0 0 0" childclass="limb">
      <site name="first" pos="1e-07 2.5e-08 123456789012.5"/>
      <joint name="shoulder" type="hinge" limited="true" range="-1 1" user="1 2 3 4 5 6 7"/>
      <geom name="g1" type="capsule" size="0.04 0.2" material="steel"/>
      <body name="fore" euler="0.5 -0.25 1e-10">
        <joint name="elbow" class="finger"/>
        <geom type="sphere" size="0.05" contype="-2147483648" conaffinity="7"/>
      </body>
      <site name="last"/>
      <camera name="eye" resolution="640 480" output="depth" fovy="45"/>
    </body>
    <frame name="f" pos="1 2 3">
      <geom type="box" size="1 1 1"/>
    </frame>
  </worldbody>
  <actuator>
    <pid name="p" joint="elbow" kp="1e3" input="pos ff" ctrlrange="-1.5 1.5"/>
    <motor name="m" joint="shoulder" gear="1e+2"/>
  </actuator>
  <sensor>
    <jointpos name="s" joint="shoulder" noise="0.1"/>
    <framepos name="fp" objtype="xbody" objname="upper"/>
  </sensor>
  <keyframe>
    <key name="home" qpos="0.1 -0" time="1e-5"/>
  </keyframe>
</mujoco>
"""


def _float_bits(values: object) -> list[bytes]:
    array = np.asarray(values, dtype=np.float64).ravel()
    return [struct.pack("<d", float(x)) for x in array.tolist()]


def _same_value(a: object, b: object) -> bool:
    """Equal, and bit for bit for floats (so -0.0 != 0.0); a reference by its target's name."""
    if isinstance(a, Element) or isinstance(b, Element):
        a = a.get_attributes().get("name") if isinstance(a, Element) else a
        b = b.get_attributes().get("name") if isinstance(b, Element) else b
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        a_array, b_array = np.asarray(a), np.asarray(b)
        return a_array.dtype == b_array.dtype and a_array.tobytes() == b_array.tobytes()
    if isinstance(a, float) and isinstance(b, float):
        return _float_bits(a) == _float_bits(b)
    return type(a) is type(b) and a == b



def _not_in_this_release() -> str | None:
    """Why DOCUMENT, written in the newest release's grammar, cannot be read here: it uses
    what the installed (older) MuJoCo lacks (``nox -s releases``); None when it can."""
    try:
        mjcf.from_xml_string(DOCUMENT)
    except mjcf.MjcfError as error:
        return str(error) if "needs MuJoCo" in str(error) else None
    return None


_OLDER = _not_in_this_release()
# the tests reading DOCUMENT: on an older MuJoCo lacking something it uses, skipped saying what
needs_document = pytest.mark.skipif(_OLDER is not None, reason=f"DOCUMENT: {_OLDER}")

def _elements(model: Element) -> list[tuple[str, object]]:
    return [(e.tag, e.get_attributes().get("name")) for e in model.iter_elements()]


@needs_document
def test_document_with_every_kind_of_value_round_trips() -> None:
    model = mjcf.from_xml_string(DOCUMENT)
    xml = model.to_xml_string()
    again = mjcf.from_xml_string(xml)
    assert again.to_xml_string() == xml  # a fixed point after the first export
    assert "<!--" not in xml  # only comments are dropped
    # element order and names
    assert _elements(again) == _elements(model)
    assert [(e.tag, e.get_attributes().get("name")) for e in model.worldbody.body[0].get_children()
            ] == [("site", "first"), ("joint", "shoulder"), ("geom", "g1"), ("body", "fore"),
                  ("site", "last"), ("camera", "eye")]
    # every attribute, exactly
    for before, after in zip(model.iter_elements(), again.iter_elements(), strict=True):
        a, b = before.get_attributes(), after.get_attributes()
        assert a.keys() == b.keys(), before.path
        for key in a:
            assert _same_value(a[key], b[key]), (before.path, key, a[key], b[key])
    assert validate(again) == validate(model) == []
    mujoco.MjSpec.from_string(xml)  # and MuJoCo reads what we wrote


@needs_document
def test_values_are_read_bit_for_bit() -> None:
    model = mjcf.from_xml_string(mjcf.from_xml_string(DOCUMENT).to_xml_string())
    upper = model.find("body", "upper")
    assert isinstance(upper, mjcf.Body) and upper.pos is not None
    assert _float_bits(upper.pos) == _float_bits([0.1, 1 / 3, -0.0])
    site = model.find("site", "first")
    assert isinstance(site, mjcf.Site) and site.pos is not None
    assert _float_bits(site.pos) == _float_bits([1e-7, 2.5e-8, 123456789012.5])
    geom_default = model.default.default[0].geom
    assert geom_default.friction is not None
    assert _float_bits(geom_default.friction) == _float_bits([1e-300, TINY, 1.7976931348623157e308])
    assert geom_default.rgba is not None and geom_default.rgba.dtype == np.float32
    assert geom_default.rgba.tolist() == np.array([0.1, 0.2, 0.3, 1 / 3], np.float32).tolist()
    material = model.find("material", "steel")
    assert isinstance(material, mjcf.Material) and material.texrepeat is not None
    assert _float_bits(material.texrepeat) == _float_bits([2.5, -0.0])
    key = model.find("key", "home")
    assert isinstance(key, mjcf.Key) and key.time == 1e-5


@needs_document
@pytest.mark.parametrize("canonical", [False, True])
def test_mujoco_compiles_the_export_to_the_documents_model(canonical: bool) -> None:
    """What the library writes for the document, MuJoCo compiles to the model it compiles
    from the document itself (every field of the MjModel compared)."""
    expected = mujoco.MjModel.from_xml_string(DOCUMENT)
    written = mjcf.from_xml_string(DOCUMENT).to_xml_string(canonical=canonical)
    assert model_differences(expected, mujoco.MjModel.from_xml_string(written)) == []


@needs_document
def test_ints_keywords_and_flags_are_canonical() -> None:
    model = mjcf.from_xml_string(DOCUMENT)
    assert model.option.iterations == 2**31 - 1
    assert model.option.actuatorgroupdisable is not None
    assert model.option.actuatorgroupdisable.tolist() == [0, 5, 30]
    geoms = model.find_all("geom")
    contype = [g.get_attributes().get("contype") for g in geoms]
    assert -(2**31) in contype
    assert model.compiler.angle == "radian" and model.compiler.autolimits is True
    assert model.compiler.eulerseq == "XyZ"  # case is meaningful here: kept as written
    assert model.option.integrator == "implicitfast"
    assert model.option.flag.contact == "disable" and model.option.flag.energy == "enable"
    xml = model.to_xml_string()
    assert 'type="plane"' in xml and 'type="hinge"' in xml and 'objtype="xbody"' in xml
    assert 'input="pos ff"' in xml
    assert 'output="depth"' in xml
    assert 'integrator="implicitfast"' in xml
    # given in Python in another case or order (as dm_control takes them): stored canonical
    model.compiler.angle = "RADIAN"
    model.option.integrator = "implicitFast"
    model.option.flag.contact = "Disable"
    pid = model.find("actuator", "p")
    assert isinstance(pid, mjcf.Pid)
    pid.input = ("ff", "pos")
    assert pid.input == ("pos", "ff")  # MuJoCo reads servo inputs only in this order
    assert model.to_xml_string() == xml


@needs_document
def test_what_mujoco_writes_back_reads_the_same() -> None:
    model = mjcf.from_xml_string(DOCUMENT)
    spec = mujoco.MjSpec.from_string(model.to_xml_string())
    spec.compile()
    theirs = mjcf.from_xml_string(spec.to_xml())
    pid = theirs.find("actuator", "p")  # MuJoCo writes every actuator as a <general>
    assert isinstance(pid, mjcf.General) and pid.input == ("pos", "ff")
    names = [b.get_attributes().get("name") for b in theirs.find_all("body")]
    assert names == ["upper", "fore"]
    upper = theirs.find("body", "upper")
    assert isinstance(upper, mjcf.Body) and upper.pos is not None
    assert upper.pos.tolist() == pytest.approx([0.1, 1 / 3, 0.0], rel=1e-6)  # MuJoCo: %g

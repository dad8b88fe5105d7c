"""Rows whose MuJoCo reader ignores attributes it does not know (``<frame>``, ``<replicate>``,
found by the generator's probe): a file giving them one loads, with a warning, as in MuJoCo."""

from __future__ import annotations

import warnings
from pathlib import Path

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support.ignored_attributes import MODEL


def test_an_attribute_mujoco_ignores_loads_with_a_warning_and_is_dropped(tmp_path: Path) -> None:
    path = tmp_path / "m.xml"
    path.write_text(MODEL, encoding="utf-8")
    with pytest.warns(mjcf.IgnoredAttributeWarning) as caught:
        model = mjcf.from_path(path)
    messages = [str(warning.message) for warning in caught]
    assert {warning.filename for warning in caught} == {__file__}  # the line that loaded it
    dropped = "MuJoCo ignores it, and so it is dropped"
    assert messages == [
        f"{path}:3: <replicate> (worldbody/replicate[0]) has no attribute prefix='p_'; {dropped}",
        f"{path}:7: <frame> (worldbody/frame[0]) has no attribute bogus='x'; {dropped}",
    ]
    assert "prefix" not in model.to_xml_string() and "bogus" not in model.to_xml_string()
    ours, theirs = model.compile(), mujoco.MjModel.from_xml_string(MODEL)
    assert [ours.geom(i).name for i in range(ours.ngeom)] == ["g0", "g1", "h"]
    assert [theirs.geom(i).name for i in range(theirs.ngeom)] == ["g0", "g1", "h"]
    np.testing.assert_array_equal(ours.geom_pos, theirs.geom_pos)


def test_the_warning_can_be_made_an_error() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", mjcf.IgnoredAttributeWarning)
        with pytest.raises(mjcf.IgnoredAttributeWarning, match="prefix=.p_."):
            mjcf.from_xml_string(MODEL)


def test_other_rows_still_refuse_an_attribute_they_do_not_have() -> None:
    text = '<mujoco><worldbody><body bogus="1"/></worldbody></mujoco>'
    with pytest.raises(mjcf.ParseError, match="<body> has no attribute 'bogus'"):
        mjcf.from_xml_string(text)
    with pytest.raises(ValueError, match="unrecognized attribute: 'bogus'"):
        mujoco.MjModel.from_xml_string(text)  # MuJoCo refuses it too


def test_python_code_never_sets_an_unknown_attribute_even_where_mujoco_ignores_it() -> None:
    model = mjcf.RootElement()
    frame = model.worldbody.add_frame()
    with pytest.raises(mjcf.UnknownAttributeError):
        frame.set_attributes(bogus="x")
    with pytest.raises(mjcf.UnknownAttributeError):
        model.worldbody.add("replicate", count=2, prefix="p_")

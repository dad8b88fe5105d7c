"""The bindings table (schema/bindings.json) against the installed mujoco, and its hand facts.

A failure of the first test means MuJoCo's arrays moved: run ``nox -s generate`` and review
the diff of schema/bindings.json and generated/typed_mjcf_generated/bindings.py(i).
"""

from __future__ import annotations

import difflib
from pathlib import Path

import mujoco
import pytest

from codegen import bindings, ir


def test_the_committed_table_is_the_installed_mujocos() -> None:
    fresh = bindings.dumps(bindings.read_wheel())
    committed = bindings.BINDINGS_PATH.read_text(encoding="utf-8")
    assert fresh == committed, "schema/bindings.json differs from the installed mujoco:\n" + (
        "".join(difflib.unified_diff(committed.splitlines(True), fresh.splitlines(True),
                                     "schema/bindings.json", "installed mujoco", n=1)))


def test_every_array_of_a_kind_has_its_first_dimension() -> None:
    """Derived, not listed: a joint binds exactly the arrays sized njnt, nq and nv."""
    table = bindings.load()
    views = {k.kind: k for k in bindings.kind_views(ir.load(), table)}
    joint = {a.field for a in views["joint"].attributes}
    model = mujoco.MjModel.from_xml_string(
        "<mujoco><worldbody><body><joint name='a' type='ball'/><geom size='1'/></body>"
        "</worldbody></mujoco>")
    data = mujoco.MjData(model)
    sized = {name for struct, source in (("MjModel", model), ("MjData", data))
             for name, spec in bindings.load()["fields"][struct].items()  # type: ignore[index]
             if spec["dims"] and spec["dims"][0] in ("njnt", "nq", "nv")
             and hasattr(source, name)}
    assert joint == sized
    # a ball joint has four qpos rows and three dofs: the sizes the generated table owns
    assert data.qpos.shape == (4,) and model.dof_damping.shape == (3,)
    assert {"qpos", "qvel", "qfrc_applied", "range", "damping", "dof_solref"} <= {
        a.name for a in views["joint"].attributes}
    assert {"ctrl", "gear", "act"} <= {a.name for a in views["actuator"].attributes}
    assert {"rgba", "xpos", "size"} <= {a.name for a in views["geom"].attributes}


def test_hand_facts_name_only_what_mujoco_has(tmp_path: Path) -> None:
    text = bindings.FACTS_PATH.read_text(encoding="utf-8")
    broken = tmp_path / "bindings.toml"
    broken.write_text(text.replace('adr = "jnt_qposadr"', 'adr = "jnt_qposaddr"'),
                      encoding="utf-8")
    with pytest.raises(bindings.BindingFactsError, match="jnt_qposaddr"):
        bindings.read_wheel(bindings.load_facts(broken))
    unknown = tmp_path / "unknown.toml"
    unknown.write_text(text + "\n[extra]\nkey = 1\n", encoding="utf-8")
    with pytest.raises(bindings.BindingFactsError, match="unknown keys"):
        bindings.load_facts(unknown)

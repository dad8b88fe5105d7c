"""The dm_control-style example of the seed documentation runs unchanged but for its import."""

from __future__ import annotations

import textwrap

import mujoco
import pytest

SEED_EXAMPLE = textwrap.dedent("""
    mjcf_model = mjcf.RootElement(model='arm')
    upper_arm = mjcf_model.worldbody.add('body', name='upper_arm')
    upper_arm.add('geom', name='upper_arm', type='capsule',
                  fromto=[0, 0, 0, 0, 0, 0.4], size=[0.05])
    shoulder = upper_arm.add('joint', name='shoulder', type='hinge', axis=[0, 1, 0])
    forearm = upper_arm.add('body', name='forearm')
    forearm.add('geom', name='forearm', type='capsule',
                fromto=[0, 0, 0, 0, 0, 0.35], size=[0.04])
    elbow = forearm.add('joint', name='elbow', type='hinge', axis=[0, 1, 0])
    forearm.pos = [0, 0, 0.45]
    forearm.geom[0].rgba = [1, 0, 0, 1]
    mjcf_model.actuator.add('motor', name='shoulder_motor', joint='shoulder')
    mjcf_model.actuator.add('motor', name='elbow_motor', joint='elbow')
    mjcf_model.sensor.add('jointpos', name='elbow_angle', joint=elbow)
    xml_string = mjcf_model.to_xml_string()
""")


def run(import_line: str) -> str:
    namespace: dict[str, object] = {}
    exec(import_line + "\n" + SEED_EXAMPLE, namespace)
    xml = namespace["xml_string"]
    assert isinstance(xml, str)
    return xml


def test_seed_example_runs_with_typed_mjcf_and_compiles() -> None:
    xml = run("import typed_mjcf as mjcf")
    model = mujoco.MjModel.from_xml_string(xml)
    assert (model.nbody, model.njnt, model.nu, model.nsensor) == (3, 2, 2, 1)
    assert 'class="/"' not in xml  # plain MJCF, unlike dm_control's output
    assert '<body name="forearm" pos="0 0 0.45">' in xml
    assert 'rgba="1 0 0 1"' in xml


def test_seed_example_compiles_to_the_same_model_as_with_dm_control() -> None:
    pytest.importorskip("dm_control")
    ours = mujoco.MjModel.from_xml_string(run("import typed_mjcf as mjcf"))
    theirs = mujoco.MjModel.from_xml_string(run("from dm_control import mjcf"))
    for field in ("body_pos", "geom_size", "geom_rgba", "jnt_axis", "actuator_trnid",
                  "sensor_objid", "geom_pos", "body_mass"):
        assert (getattr(ours, field) == getattr(theirs, field)).all(), field

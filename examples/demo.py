"""Build a small articulated robot with the typed API, compile it, simulate one second.

Two position servos drive a two-link arm to target angles; the demo prints each target next
to what the simulation reached, and where the hand ended up next to where the targets put it.

    nox -s demo            # or: python examples/demo.py [--out DIR]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import mujoco
import numpy as np
from numpy.typing import NDArray

import typed_mjcf as mjcf

TARGETS = {"shoulder": 0.8, "elbow": -1.0}  # servo targets, radians


def build_arm() -> mjcf.RootElement:
    """A two-link arm on a base, with position servos, sensors and a target."""
    model = mjcf.RootElement(model="two_link_arm")
    model.compiler.angle = "radian"
    model.option.timestep = 0.002
    model.option.integrator = "implicitfast"

    model.default.add_joint(damping=0.5, armature=0.01)
    model.default.add_geom(rgba=(0.8, 0.6, 0.4, 1.0), density=500.0)

    grid = model.asset.add_texture(name="grid", type="2d", builtin="checker",
                                   rgb1=(0.2, 0.3, 0.4), rgb2=(0.1, 0.2, 0.3),
                                   width=256, height=256)
    model.asset.add_material(name="floor", texture=grid, texrepeat=(4.0, 4.0))

    world = model.worldbody
    world.add_light(pos=(0.0, 0.0, 3.0), dir=(0.0, 0.0, -1.0))
    world.add_geom(name="floor", type="plane", size=(2.0, 2.0, 0.1), material="floor")

    base = world.add_body(name="base", pos=(0.0, 0.0, 0.1))
    base.add_geom(type="cylinder", size=(0.1, 0.05))

    # gravcomp: the servos then hold their targets exactly instead of sagging under gravity.
    upper = base.add_body(name="upper_arm", pos=(0.0, 0.0, 0.05), gravcomp=1.0)
    shoulder = upper.add_joint(name="shoulder", type="hinge", axis=(0.0, 1.0, 0.0),
                               range=(-1.5, 1.5))
    upper.add_geom(type="capsule", fromto=(0.0, 0.0, 0.0, 0.0, 0.0, 0.4), size=(0.04,))
    # The base is welded to the world, so MuJoCo's parent-child filter does not apply: the
    # capsule's end, sunk into the base at the shoulder, would push against it.
    model.contact.add_exclude(body1=base, body2=upper)

    fore = upper.add_body(name="forearm", pos=(0.0, 0.0, 0.4), gravcomp=1.0)
    elbow = fore.add_joint(name="elbow", type="hinge", axis=(0.0, 1.0, 0.0), range=(-2.0, 2.0))
    fore.add_geom(type="capsule", fromto=(0.0, 0.0, 0.0, 0.0, 0.0, 0.35), size=(0.035,))
    fore.add_site(name="hand", pos=(0.0, 0.0, 0.35), size=(0.02,))

    for joint in (shoulder, elbow):
        model.actuator.add_position(name=f"{joint.name}_servo", joint=joint, kp=20.0,
                                    dampratio=1.0, ctrlrange=(-1.5, 1.5))
        model.sensor.add_jointpos(name=f"{joint.name}_angle", joint=joint)
    model.sensor.add_framepos(name="hand_position", objtype="site", objname="hand")
    model.keyframe.add_key(name="bent", qpos=(0.5, -0.8))
    return model


def simulate(model: mjcf.RootElement, seconds: float = 1.0) -> tuple[mujoco.MjModel, mujoco.MjData]:
    compiled = model.compile()
    data = mujoco.MjData(compiled)
    for joint, target in TARGETS.items():
        data.actuator(f"{joint}_servo").ctrl = target
    while data.time < seconds:
        mujoco.mj_step(compiled, data)
    return compiled, data


def hand_at_targets(compiled: mujoco.MjModel) -> NDArray[np.float64]:
    """Where the hand is when every joint is at its target (MuJoCo's forward kinematics)."""
    data = mujoco.MjData(compiled)
    for joint, target in TARGETS.items():
        data.joint(joint).qpos = target
    mujoco.mj_kinematics(compiled, data)
    return data.site("hand").xpos.copy()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", type=Path, default=Path("out"), help="where to write the XML")
    args = parser.parse_args()

    model = build_arm()
    compiled, data = simulate(model)
    print(f"model {model.model!r}: {compiled.nbody} bodies, {compiled.njnt} joints, "
          f"{compiled.nu} actuators, {compiled.nsensor} sensors")
    print(f"after {data.time:.3f} s:")
    for joint, target in TARGETS.items():
        reached = data.sensor(f"{joint}_angle").data[0]
        print(f"  {joint:<8}  target {np.degrees(target):+6.1f} deg  "
              f"reached {np.degrees(reached):+6.1f} deg")
    goal = hand_at_targets(compiled)
    hand = data.sensor("hand_position").data
    print(f"  hand      target ({goal[0]:+.3f}, {goal[1]:+.3f}, {goal[2]:+.3f}) m  "
          f"reached ({hand[0]:+.3f}, {hand[1]:+.3f}, {hand[2]:+.3f}) m  "
          f"error {np.linalg.norm(hand - goal) * 1000:.1f} mm")
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "two_link_arm.xml"
    path.write_text(model.to_xml_string(), encoding="utf-8")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()

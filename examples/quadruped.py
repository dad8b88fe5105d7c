"""A quadruped trotting over rough ground: default classes, a heightfield, touch sensors.

The robot is built once with nested default classes (every leg shares its joint, geom,
site and servo settings; nothing is repeated per leg), stands on a procedurally generated
heightfield, and trots with an open-loop gait. Touch sensors on the feet show the gait:
diagonal feet (front-left with hind-right, front-right with hind-left) touch down together.

    python examples/quadruped.py [--seconds 4] [--out DIR]
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import mujoco
import numpy as np
from numpy.typing import NDArray

import typed_mjcf as mjcf

# Leg name -> (x, y) of the hip on the torso, and the trot phase: diagonal pairs move together.
LEGS = {"fl": (0.2, 0.12, 0.0), "fr": (0.2, -0.12, 0.5),
        "hl": (-0.2, 0.12, 0.5), "hr": (-0.2, -0.12, 0.0)}
THIGH, SHIN = 0.16, 0.16  # segment lengths, m
STANCE = {"hip": 0.5, "knee": -1.0}  # standing joint angles, rad: a knee bent backwards
TERRAIN_HEIGHT = 0.05  # m, top of the highest bump above the lowest point


def terrain(rows: int = 64, seed: int = 0) -> NDArray[np.float64]:
    """Smooth random bumps in [0, 1]: a sum of a few sinusoids with random phases."""
    rng = np.random.default_rng(seed)
    y, x = np.mgrid[0:rows, 0:rows] / rows * 2 * np.pi
    height = np.zeros((rows, rows))
    for kx, ky in rng.integers(1, 6, size=(6, 2)):
        height += np.sin(kx * x + rng.uniform(0, 2 * np.pi)) * np.sin(ky * y)
    low, high = float(height.min()), float(height.max())
    return (height - low) / (high - low)


def build() -> mjcf.RootElement:
    model = mjcf.RootElement(model="quadruped")
    model.compiler.angle = "radian"
    model.option.timestep = 0.002
    model.option.integrator = "implicitfast"

    # Default classes: "robot" holds what every part of the robot shares, nested "leg" and
    # "foot" classes refine it. Bodies pick them with childclass / class_.
    robot = model.default.add_default(class_="robot")
    robot.add_joint(type="hinge", axis=(0, 1, 0), damping=0.5, armature=0.01,
                    range=(-1.8, 1.8))
    robot.add_geom(type="capsule", density=800.0, rgba=(0.3, 0.45, 0.6, 1), condim=3)
    robot.add_position(kp=40.0, dampratio=0.5, ctrlrange=(-1.8, 1.8))
    leg = robot.add_default(class_="leg")
    leg.add_geom(size=(0.022,))
    foot = robot.add_default(class_="foot")
    foot.add_geom(type="sphere", size=(0.03,), friction=(1.2, 0.02, 0.01),
                  rgba=(0.15, 0.15, 0.15, 1))
    # A touch sensor sums the contact forces whose points lie inside its site: a little
    # larger than the foot, so that every contact of the foot is counted.
    foot.add_site(type="sphere", size=(0.035,), rgba=(0.9, 0.3, 0.2, 0.3))

    rows = 64
    elevation = terrain(rows)
    model.asset.add_hfield(name="terrain", nrow=rows, ncol=rows,
                           size=(4.0, 4.0, TERRAIN_HEIGHT, 0.1), elevation=elevation.ravel())
    grid = model.asset.add_texture(name="grid", type="2d", builtin="checker", width=128,
                                   height=128, rgb1=(0.35, 0.4, 0.3), rgb2=(0.3, 0.35, 0.25))
    ground = model.asset.add_material(name="ground", texture=grid, texrepeat=(16, 16))

    world = model.worldbody
    world.add_light(pos=(0, 0, 4), dir=(0, 0, -1), directional=True)
    world.add_geom(name="terrain", type="hfield", hfield="terrain", material=ground)

    torso = world.add_body(name="torso", childclass=robot,
                           pos=(0, 0, TERRAIN_HEIGHT + THIGH + SHIN))
    torso.add_freejoint(name="root")
    torso.add_geom(name="torso", type="box", size=(0.24, 0.1, 0.04))
    torso.add_site(name="imu", size=(0.01,))
    for name, (x, y, _) in LEGS.items():
        thigh = torso.add_body(name=f"{name}_thigh", pos=(x, y, 0), childclass=leg)
        thigh.add_joint(name=f"{name}_hip")
        thigh.add_geom(fromto=(0, 0, 0, 0, 0, -THIGH))
        shin = thigh.add_body(name=f"{name}_shin", pos=(0, 0, -THIGH))
        shin.add_joint(name=f"{name}_knee")
        shin.add_geom(fromto=(0, 0, 0, 0, 0, -SHIN))
        tip = shin.add_body(name=f"{name}_foot", pos=(0, 0, -SHIN), childclass=foot)
        tip.add_geom(name=f"{name}_foot")
        model.sensor.add_touch(name=f"{name}_touch", site=tip.add_site(name=f"{name}_foot"))
        for joint in ("hip", "knee"):
            model.actuator.add_position(name=f"{name}_{joint}", joint=f"{name}_{joint}",
                                        class_=robot)
    model.sensor.add_framepos(name="torso_position", objtype="site", objname="imu")
    model.sensor.add_framezaxis(name="torso_up", objtype="site", objname="imu")

    # Standing pose: free joint (position, quaternion), then hip and knee of each leg.
    stance = [STANCE["hip"], STANCE["knee"]] * len(LEGS)
    model.keyframe.add_key(name="stand", qpos=[0, 0, TERRAIN_HEIGHT + 0.3, 1, 0, 0, 0, *stance],
                           ctrl=stance)
    return model


def trot(time: float, phase: float, frequency: float = 2.0) -> tuple[float, float]:
    """Hip and knee targets of a leg: swing the hip, lift the foot in the forward swing."""
    angle = 2 * math.pi * (frequency * time + phase)
    hip = STANCE["hip"] - 0.3 * math.sin(angle)
    knee = STANCE["knee"] - 0.6 * max(0.0, math.cos(angle))
    return hip, knee


def simulate(model: mjcf.RootElement, seconds: float) -> None:
    compiled = model.compile()
    data = mujoco.MjData(compiled)
    mujoco.mj_resetDataKeyframe(compiled, data, compiled.key("stand").id)
    while data.time < 0.5:  # settle on the ground before walking
        mujoco.mj_step(compiled, data)
    start = data.sensor("torso_position").data.copy()

    touch_steps = dict.fromkeys(LEGS, 0)
    both_diagonal = 0  # steps with a diagonal pair down and the other pair in the air
    steps, lowest_up = 0, 1.0
    t0 = data.time
    while data.time < t0 + seconds:
        for name, (_, _, phase) in LEGS.items():
            hip, knee = trot(data.time - t0, phase)
            data.actuator(f"{name}_hip").ctrl = hip
            data.actuator(f"{name}_knee").ctrl = knee
        mujoco.mj_step(compiled, data)
        down = {name: data.sensor(f"{name}_touch").data[0] > 0 for name in LEGS}
        for name, touching in down.items():
            touch_steps[name] += touching
        pair_a = down["fl"] and down["hr"] and not (down["fr"] or down["hl"])
        pair_b = down["fr"] and down["hl"] and not (down["fl"] or down["hr"])
        both_diagonal += pair_a or pair_b
        lowest_up = min(lowest_up, float(data.sensor("torso_up").data[2]))
        steps += 1

    end = data.sensor("torso_position").data
    classes = ", ".join(d.class_ for d in model.find_all("default") if d.class_ is not None)
    travel = end - start
    print(f"model {model.model!r}: {compiled.nbody} bodies, {compiled.njnt} joints, "
          f"{compiled.nu} servos, {compiled.nsensor} sensors, "
          f"default classes {classes}, "
          f"heightfield {compiled.hfield_nrow[0]}x{compiled.hfield_ncol[0]}")
    print(f"trotted {seconds:.1f} s at 2 Hz: moved {travel[0]:+.2f} m forward, "
          f"{travel[1]:+.2f} m sideways; torso height {end[2]:.2f} m; "
          f"stayed upright (lowest cos tilt {lowest_up:.2f})")
    print("feet on the ground: " + ", ".join(
        f"{name} {100 * count / steps:.0f}%" for name, count in touch_steps.items()))
    print(f"diagonal pairs alone on the ground: {100 * both_diagonal / steps:.0f}% of the time")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seconds", type=float, default=4.0, help="how long to trot")
    parser.add_argument("--out", type=Path, help="also write the model's XML here")
    args = parser.parse_args()
    model = build()
    simulate(model, args.seconds)
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        path = args.out / "quadruped.xml"
        path.write_text(model.to_xml_string(), encoding="utf-8")
        print(f"wrote {path}")


if __name__ == "__main__":
    main()

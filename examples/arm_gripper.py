"""A tendon-driven gripper attached to an arm, picking up a box.

Three models are built separately and composed with ``attach``, dm_control style: the
gripper at the arm's flange, the arm on a mount in the scene. The gripper's two fingers are
driven by one actuator through a fixed tendon (a differential: the tendon's length is the
sum of the fingers' travel, so each finger stops on its own when it meets the box). The arm
follows joint-space waypoints from an analytic inverse kinematics; touch sensors in the
finger pads report the grip.

    python examples/arm_gripper.py [--out DIR]
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import mujoco
import numpy as np

import typed_mjcf as mjcf

SHOULDER_HEIGHT = 0.25
UPPER, FORE, WRIST = 0.3, 0.3, 0.08  # arm link lengths, m
PINCH = 0.1  # from the flange to the point between the fingertips, m
FINGER_TRAVEL = 0.04  # each finger slides this far from open to closed, m
FINGER_Y, FINGER_HALF = 0.06, 0.008  # open fingers' centres at +-FINGER_Y; half thickness
BOX = 0.025  # half size of the box to pick, m
BOX_AT = (0.42, 0.18)  # where the box starts on the floor, m


def make_gripper() -> mjcf.RootElement:
    """A parallel gripper whose frame's z axis points from the flange to the fingertips."""
    gripper = mjcf.RootElement(model="gripper")
    # Stiffer contacts than MuJoCo's default (time constant 2 timesteps, not 10), so that
    # the fingers do not visibly sink into the light box they squeeze.
    gripper.default.add_geom(friction=(1.5, 0.02, 0.01), solref=(0.004, 1.0),
                             solimp=(0.95, 0.99, 0.001), rgba=(0.25, 0.25, 0.3, 1))
    gripper.default.add_joint(type="slide", damping=2.0, range=(0.0, FINGER_TRAVEL))

    palm = gripper.worldbody.add_body(name="palm")
    palm.add_geom(type="box", pos=(0, 0, 0.02), size=(0.02, 0.07, 0.02))
    palm.add_site(name="pinch", pos=(0, 0, PINCH), size=(0.005,), rgba=(1, 0, 0, 1))
    grip = gripper.tendon.add_fixed(name="grip", range=(0.0, 2 * FINGER_TRAVEL))
    for side, sign in (("left", 1.0), ("right", -1.0)):
        finger = palm.add_body(name=f"{side}_finger", pos=(0, sign * FINGER_Y, 0.04))
        # Positive travel closes the finger: its axis points towards the middle.
        joint = finger.add_joint(name=f"{side}_slide", axis=(0, -sign, 0))
        finger.add_geom(type="box", pos=(0, 0, 0.04), size=(0.012, FINGER_HALF, 0.04))
        # A touch sensor counts the contacts whose points lie inside its site: the pad
        # covers the finger's inner face (contact points lie between the two surfaces).
        pad = finger.add_site(name=f"{side}_pad", type="box", pos=(0, -sign * 0.006, 0.04),
                              size=(0.013, 0.006, 0.041), rgba=(0.9, 0.3, 0.2, 0.4))
        grip.add_joint(joint=joint, coef=1.0)
        gripper.sensor.add_touch(name=f"{side}_touch", site=pad)
    # One servo on the tendon: ctrl is the total closing travel of both fingers.
    gripper.actuator.add_position(name="close", tendon=grip, kp=300.0, dampratio=1.0,
                                  ctrlrange=(0.0, 2 * FINGER_TRAVEL), forcerange=(-20, 20))
    return gripper


def make_arm() -> mjcf.RootElement:
    """A four-joint arm (yaw, then three pitch joints) ending in a flange site."""
    arm = mjcf.RootElement(model="arm")
    arm.compiler.angle = "radian"
    arm.default.add_joint(type="hinge", axis=(0, 1, 0), damping=1.0, armature=0.05)
    arm.default.add_geom(type="capsule", size=(0.03,), rgba=(0.85, 0.55, 0.2, 1))
    arm.default.add_position(kp=400.0, dampratio=1.0, ctrlrange=(-3.2, 3.2))

    base = arm.worldbody.add_body(name="base")
    base.add_geom(type="cylinder", size=(0.06, SHOULDER_HEIGHT / 2),
                  pos=(0, 0, SHOULDER_HEIGHT / 2), rgba=(0.3, 0.3, 0.3, 1))
    turret = base.add_body(name="turret", pos=(0, 0, SHOULDER_HEIGHT), gravcomp=1.0)
    turret.add_joint(name="yaw", axis=(0, 0, 1))
    turret.add_geom(type="sphere", size=(0.045,))
    upper = turret.add_body(name="upper", gravcomp=1.0)
    upper.add_joint(name="shoulder")
    upper.add_geom(fromto=(0, 0, 0, 0, 0, UPPER))
    fore = upper.add_body(name="fore", pos=(0, 0, UPPER), gravcomp=1.0)
    fore.add_joint(name="elbow")
    fore.add_geom(fromto=(0, 0, 0, 0, 0, FORE), size=(0.025,))
    hand = fore.add_body(name="hand", pos=(0, 0, FORE), gravcomp=1.0)
    hand.add_joint(name="wrist")
    hand.add_geom(fromto=(0, 0, 0, 0, 0, WRIST), size=(0.02,))
    hand.add_site(name="flange", pos=(0, 0, WRIST))
    # The base is welded to the world, so MuJoCo does not filter its contacts with the link
    # above it; they touch at the turret by design.
    arm.contact.add_exclude(body1=base, body2=turret)
    for joint in arm.find_all("joint"):
        arm.actuator.add_position(name=joint.name, joint=joint)
    return arm


def make_scene() -> tuple[mjcf.RootElement, mjcf.RootElement, mjcf.RootElement]:
    arm, gripper = make_arm(), make_gripper()
    flange = arm.find("site", "flange")
    if flange is None:
        raise LookupError("the arm has no flange site")
    flange.attach(gripper)  # the gripper's names become "gripper/..." inside the arm

    scene = mjcf.RootElement(model="pick")
    scene.compiler.angle = "radian"  # as in the arm: global settings must agree to attach
    scene.option.timestep = 0.002
    scene.option.integrator = "implicitfast"
    scene.worldbody.add_light(pos=(0, 0, 3), dir=(0, 0, -1))
    scene.worldbody.add_geom(name="floor", type="plane", size=(1, 1, 0.1))
    scene.worldbody.add_site(name="mount").attach(arm)  # "arm/gripper/..." in the scene
    box = scene.worldbody.add_body(name="box", pos=(*BOX_AT, BOX))
    box.add_freejoint()
    box.add_geom(type="box", size=(BOX, BOX, BOX), density=800.0, rgba=(0.2, 0.6, 0.3, 1),
                 friction=(1.5, 0.02, 0.01))
    return scene, arm, gripper


def arm_angles(x: float, y: float, z: float) -> dict[str, float]:
    """Joint angles that put the pinch point at (x, y, z), the gripper pointing down."""
    yaw = math.atan2(y, x)
    # The wrist joint sits straight above the pinch point; solve the shoulder-elbow triangle.
    reach, height = math.hypot(x, y), z + WRIST + PINCH - SHOULDER_HEIGHT
    cos_elbow = (reach**2 + height**2 - UPPER**2 - FORE**2) / (2 * UPPER * FORE)
    elbow = math.acos(max(-1.0, min(1.0, cos_elbow)))
    shoulder = math.atan2(reach, height) - math.atan2(FORE * math.sin(elbow),
                                                      UPPER + FORE * math.cos(elbow))
    wrist = math.pi - shoulder - elbow  # links' angles from vertical add up to pointing down
    return {"yaw": yaw, "shoulder": shoulder, "elbow": elbow, "wrist": wrist}


def run(scene: mjcf.RootElement) -> None:
    compiled = scene.compile()
    data = mujoco.MjData(compiled)
    mujoco.mj_forward(compiled, data)
    box = data.body("box")
    start = box.xpos.copy()
    x, y = BOX_AT
    # (pinch point, gripper closing travel, seconds): approach, descend, grip, lift, hold.
    waypoints = [((x, y, 0.2), 0.0, 1.0), ((x, y, BOX), 0.0, 0.8),
                 ((x, y, BOX), 2 * FINGER_TRAVEL, 0.5), ((x, y, 0.25), 2 * FINGER_TRAVEL, 1.0),
                 ((x, y, 0.25), 2 * FINGER_TRAVEL, 0.5)]
    arm_servos = ["yaw", "shoulder", "elbow", "wrist"]
    current = np.array([data.actuator(f"arm/{name}").ctrl[0] for name in arm_servos])
    for target, closing, seconds in waypoints:
        goal = np.array([arm_angles(*target)[name] for name in arm_servos])
        begin, t0 = current, data.time
        while data.time < t0 + seconds:  # joint-space interpolation, eased
            s = min(1.0, (data.time - t0) / (0.7 * seconds))
            current = begin + (goal - begin) * (3 * s**2 - 2 * s**3)
            for name, angle in zip(arm_servos, current, strict=True):
                data.actuator(f"arm/{name}").ctrl = angle
            data.actuator("arm/gripper/close").ctrl = closing
            mujoco.mj_step(compiled, data)

    lift = waypoints[-1][0]
    pinch = data.site("arm/gripper/pinch").xpos
    closed_by = float(data.ten_length[compiled.tendon("arm/gripper/grip").id])
    gap = 2 * (FINGER_Y - FINGER_HALF) - closed_by
    actuators = ", ".join(compiled.actuator(i).name for i in range(compiled.nu))
    print(f"model {scene.model!r}: {compiled.nbody} bodies, {compiled.njnt} joints, "
          f"{compiled.ntendon} tendon, actuators {actuators}")
    print(f"pinch point target ({lift[0]:.3f}, {lift[1]:.3f}, {lift[2]:.3f}) m, "
          f"reached ({pinch[0]:.3f}, {pinch[1]:.3f}, {pinch[2]:.3f}) m")
    print(f"box: started at z={start[2]:.3f} m, now z={box.xpos[2]:.3f} m "
          f"(lifted {box.xpos[2] - start[2]:+.3f} m), "
          f"{np.linalg.norm(box.xpos - pinch) * 1000:.0f} mm from the pinch point")
    print(f"gap between the finger pads {gap * 1000:.1f} mm (box {2 * BOX * 1000:.0f} mm); "
          f"pads feel {data.sensor('arm/gripper/left_touch').data[0]:.1f} N and "
          f"{data.sensor('arm/gripper/right_touch').data[0]:.1f} N")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", type=Path, help="also write the composed model's XML here")
    args = parser.parse_args()
    scene, _, _ = make_scene()
    run(scene)
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        path = args.out / "arm_gripper.xml"
        path.write_text(scene.to_xml_string(), encoding="utf-8")
        print(f"wrote {path}")


if __name__ == "__main__":
    main()

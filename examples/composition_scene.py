"""MuJoCo's own composition elements, typed: frame, replicate, flexcomp, a plugin, attach.

One scene, each element doing a job and the simulation checking it:

- ``<frame>`` places a table and everything on it with one transform;
- ``<replicate>`` puts six pegs in a ring on a turntable (MuJoCo names the copies);
- ``<flexcomp>`` drops a square of cloth on the turntable, which carries it round;
- the ``mujoco.pid`` actuator plugin (bundled with MuJoCo, no extra library) turns the
  turntable to a target angle;
- ``<attach>`` hangs two pendulums from a model that exists only in memory (``mjcf.Asset``),
  released from different amplitudes: their periods are compared with the exact period of
  an ideal pendulum.

    python examples/composition_scene.py [--seconds 4] [--out DIR]
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import mujoco
import numpy as np
from numpy.typing import NDArray

import typed_mjcf as mjcf

GRAVITY = 9.81
LENGTH = 0.5  # pendulum length, m
AMPLITUDES = {"small_": 5.0, "large_": 60.0}  # attach prefix -> release angle, degrees
TURN_TO = 1.0  # turntable target, rad
TABLE_TOP = 0.42  # m
BEARING, DISC_HALF = 0.005, 0.02  # the turntable's gap above the table; half thickness, m
DISC_TOP = TABLE_TOP + BEARING + 2 * DISC_HALF
CLOTH_RADIUS = 0.01  # of the cloth's vertices, m
CLOTH_ROW = 7  # vertices per row and column
TURN_AT = 1.0  # s: the turntable starts turning once the cloth has landed on it


def make_pendulum() -> mjcf.RootElement:
    """An ideal pendulum: all its mass in a point at the end of a massless rod."""
    pendulum = mjcf.RootElement(model="pendulum")
    pendulum.compiler.angle = "radian"
    arm = pendulum.worldbody.add_body(name="arm")
    arm.add_joint(name="swing", type="hinge", axis=(0, 1, 0))
    # The inertial element fixes the mass distribution; the geoms are drawn only.
    arm.add_inertial(pos=(0, 0, -LENGTH), mass=1.0, diaginertia=(1e-9, 1e-9, 1e-9))
    pendulum.default.add_geom(contype=0, conaffinity=0, mass=0.0, rgba=(0.7, 0.7, 0.75, 1))
    arm.add_geom(type="capsule", fromto=(0, 0, 0, 0, 0, -LENGTH), size=(0.005,))
    arm.add_geom(type="sphere", pos=(0, 0, -LENGTH), size=(0.03,))
    return pendulum


def build() -> mjcf.RootElement:
    model = mjcf.RootElement(model="composition")
    model.compiler.angle = "radian"
    model.option.timestep = 0.002
    model.option.integrator = "implicitfast"
    model.option.gravity = (0, 0, -GRAVITY)
    model.worldbody.add_light(pos=(0, 0, 3), dir=(0, 0, -1))
    model.worldbody.add_geom(name="floor", type="plane", size=(2, 2, 0.1))

    # A PID controller from MuJoCo's bundled plugins: one instance, configured by key/value.
    pid = model.extension.add_plugin(plugin="mujoco.pid").add_instance(name="turntable_pid")
    for key, value in (("kp", "20"), ("ki", "5"), ("kd", "2")):
        pid.add_config(key=key, value=value)

    # Everything on the table is placed in the table's frame, whose origin is the table top.
    table = model.worldbody.add_frame(name="table", pos=(0, 0, TABLE_TOP))
    table.add_geom(type="box", pos=(0, 0, -0.02), size=(0.5, 0.5, 0.02), rgba=(0.6, 0.45, 0.3, 1))
    leg = (TABLE_TOP - 0.04) / 2  # half height
    for x in (-0.45, 0.45):
        for y in (-0.45, 0.45):
            table.add_geom(type="box", pos=(x, y, -0.04 - leg), size=(0.03, 0.03, leg))
    # The turntable: a disc on a bearing, just above the table top.
    turntable = table.add_body(name="turntable", pos=(0, 0, BEARING + DISC_HALF))
    spin = turntable.add_joint(name="spin", type="hinge", axis=(0, 0, 1), damping=0.1)
    turntable.add_geom(type="cylinder", size=(0.3, DISC_HALF), rgba=(0.3, 0.3, 0.35, 1))
    ring = turntable.add_replicate(count=6, euler=(0, 0, math.pi / 3), sep="_")
    peg = ring.add_body(name="peg", pos=(0.26, 0, DISC_HALF + 0.04))  # standing on the disc
    peg.add_geom(type="box", size=(0.02, 0.02, 0.04), rgba=(0.2, 0.5, 0.8, 1))
    model.actuator.add_plugin(name="turn", joint=spin, plugin="mujoco.pid", instance=pid,
                              actdim=1)

    # A square of cloth, small enough to land on the disc inside the ring of pegs.
    cloth = model.worldbody.add_flexcomp(name="cloth", type="grid", dim=2, count=(CLOTH_ROW, CLOTH_ROW, 1),
                                         spacing=(0.05, 0.05, 0.05), pos=(0, 0, 0.8),
                                         radius=CLOTH_RADIUS, mass=0.2, rgba=(0.8, 0.2, 0.3, 1))
    cloth.add_edge(equality=True)  # inextensible edges: the grid hangs like cloth
    cloth.add_contact(selfcollide="none")

    # The pendulum model is never written to disk: its XML goes to MuJoCo as an asset.
    xml = make_pendulum().to_xml_string()
    pendulum = model.asset.add_model(name="pendulum", file=mjcf.Asset(xml, ".xml", "pendulum"))
    gantry = model.worldbody.add_body(name="gantry", pos=(0, 0.8, 1.2))
    gantry.add_geom(type="capsule", fromto=(-0.5, 0, 0, 0.5, 0, 0), size=(0.02,))
    for x, prefix in zip((-0.3, 0.3), AMPLITUDES, strict=True):
        hook = gantry.add_frame(pos=(x, 0, 0))
        hook.add_attach(model=pendulum, body="arm", prefix=prefix)
    return model


def exact_period(amplitude: float) -> float:
    """The period of an ideal pendulum released at ``amplitude`` (rad), by the complete
    elliptic integral of the first kind (arithmetic-geometric mean)."""
    a, b = 1.0, math.cos(amplitude / 2)
    while abs(a - b) > 1e-15:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return 2 * math.pi * math.sqrt(LENGTH / GRAVITY) / a


def measured_period(times: NDArray[np.float64], angles: NDArray[np.float64]) -> float:
    """Twice the mean time between zero crossings (linearly interpolated between steps);
    NaN with fewer than two crossings."""
    at = np.flatnonzero(np.signbit(angles[:-1]) != np.signbit(angles[1:]))
    crossings = times[at] - angles[at] * (times[at + 1] - times[at]) / (angles[at + 1]
                                                                        - angles[at])
    return 2 * float(np.mean(np.diff(crossings))) if len(crossings) > 1 else math.nan


def heading(points: NDArray[np.float64]) -> float:
    """The direction (rad, about z) of the cloth's first row, from its first to last vertex."""
    edge = points[CLOTH_ROW - 1] - points[0]
    return math.atan2(edge[1], edge[0])


def simulate(model: mjcf.RootElement, seconds: float) -> None:
    compiled = model.compile()
    data = mujoco.MjData(compiled)
    for prefix, degrees in AMPLITUDES.items():
        data.joint(f"{prefix}swing").qpos = math.radians(degrees)
    mujoco.mj_forward(compiled, data)
    first = compiled.flex_vertadr[0]
    cloth = data.flexvert_xpos[first:first + compiled.flex_vertnum[0]]  # a live view
    start = heading(cloth)

    steps = round(seconds / compiled.opt.timestep)
    times = np.empty(steps)
    swings = {prefix: np.empty(steps) for prefix in AMPLITUDES}
    for i in range(steps):
        if data.time >= TURN_AT:  # the cloth has landed: turn it with the turntable
            data.actuator("turn").ctrl = TURN_TO
        mujoco.mj_step(compiled, data)
        times[i] = data.time
        for prefix, trace in swings.items():
            trace[i] = data.joint(f"{prefix}swing").qpos[0]

    pegs = [compiled.body(i).name for i in range(compiled.nbody)
            if compiled.body(i).name.startswith("peg")]
    print(f"model {model.model!r}: {compiled.nbody} bodies, {compiled.njnt} joints, "
          f"{compiled.nflex} flex ({compiled.nflexvert} vertices), {compiled.nplugin} plugin")
    print(f"replicate made {len(pegs)} pegs: {', '.join(pegs)}")
    print(f"turntable (pid plugin): target {TURN_TO:.3f} rad, reached "
          f"{data.joint('spin').qpos[0]:.3f} rad after {data.time - TURN_AT:.1f} s")
    print(f"cloth: resting at z {cloth[:, 2].min():.3f} to {cloth[:, 2].max():.3f} m "
          f"(turntable top + vertex radius: {DISC_TOP + CLOTH_RADIUS:.3f} m), "
          f"carried round by {heading(cloth) - start:.3f} rad")
    for prefix, degrees in AMPLITUDES.items():
        period = measured_period(times, swings[prefix])
        print(f"pendulum {prefix}: released at {degrees:.0f} deg, period {period:.4f} s, "
              f"exact {exact_period(math.radians(degrees)):.4f} s")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seconds", type=float, default=4.0, help="how long to simulate")
    parser.add_argument("--out", type=Path, help="also write the model's files here")
    args = parser.parse_args()
    if args.seconds < TURN_AT + 1.5:
        parser.error(f"--seconds must be at least {TURN_AT + 1.5}: the turntable starts at "
                     f"{TURN_AT} s, and the pendulums need two swings")
    model = build()
    simulate(model, args.seconds)
    if args.out is not None:  # the XML and the in-memory pendulum model, as files
        path = mjcf.export_with_assets(model, args.out, "composition_scene.xml",
                                       overwrite=True)
        print(f"wrote {path} and {len(model.get_assets())} asset(s) beside it")


if __name__ == "__main__":
    main()

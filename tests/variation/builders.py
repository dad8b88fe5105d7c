"""Build functions for structural variants: module-level, so that they pickle by name to
worker processes and Ray."""

from __future__ import annotations

import numpy as np

import typed_mjcf as mjcf

SHAPES = ("sphere", "box", "capsule", "ellipsoid", "cylinder")


def gripper(rng: np.random.Generator) -> mjcf.RootElement:
    """One of two small grippers, as a model to attach."""
    model = mjcf.RootElement(model="gripper")
    palm = model.worldbody.add_body(name="palm")
    fingers = int(rng.choice([2, 3]))
    for k in range(fingers):
        finger = palm.add_body(name=f"finger{k}", pos=(0.02 * k, 0, -0.05))
        finger.add_joint(name=f"slide{k}", type="slide", axis=(1, 0, 0), range=(0, 0.02))
        finger.add_geom(type="box", size=(0.005, 0.005, 0.02), mass=0.01)
    return model


def table_scene(rng: np.random.Generator, world: int) -> mjcf.RootElement:
    """A table with 1 to 5 objects of random shapes and sizes, and one of two grippers."""
    model = mjcf.RootElement(model=f"scene{world}")
    model.worldbody.add_geom(name="floor", type="plane", size=(2, 2, 0.1))
    for k in range(int(rng.integers(1, 6))):
        body = model.worldbody.add_body(name=f"object{k}", pos=(0.1 * k, 0, 0.2))
        body.add_freejoint()
        shape = SHAPES[int(rng.integers(len(SHAPES)))]
        size = tuple(float(x) for x in rng.uniform(0.01, 0.05, size=3))
        body.add_geom(name=f"geom{k}", type=shape, size=size)
    mount = model.worldbody.add_site(name="mount", pos=(0, 0, 1))
    mount.attach(gripper(rng))
    return model


def failing_at_world_3(rng: np.random.Generator, world: int) -> mjcf.RootElement:
    """Like table_scene, but world 3 gives a geom a negative size (MuJoCo refuses it)."""
    model = table_scene(rng, world)
    if world == 3:
        geom = model.find("geom", "geom0")
        assert geom is not None
        geom.size = (-0.1, 0.1, 0.1)
    return model

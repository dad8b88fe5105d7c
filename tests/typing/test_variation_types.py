"""Positive typing cases of typed_mjcf.variation: a distribution that fits an attribute is
accepted by mypy and pyright (``test_typecheck.py`` checks this file), and each is typed as
the value it stands for. Run by pytest too: every statement is valid at run time."""

from __future__ import annotations

from typing import assert_type

import typed_mjcf as mjcf
from typed_mjcf.variation import Variation, choice, log_uniform, normal, uniform


def test_fitting_distributions_type_as_their_values() -> None:
    model = mjcf.RootElement()
    body = model.worldbody.add_body(name="b")
    body.add_freejoint()
    geom = body.add_geom(name="g", size=(0.1, 0.1, 0.1), type="box")
    joint = model.worldbody.add_body(name="c").add_joint(name="j")
    v = Variation()
    assert_type(v.of(geom), mjcf.Geom)
    assert_type(uniform(0.5, 1.5), float)
    assert_type(choice(["box", "sphere"]), str)
    # friction's 1 to 3 numbers: a vector distribution, or one per component
    v.of(geom).friction = uniform((0.5, 0.005, 1e-4), (1.5, 0.01, 1e-3))
    v.of(geom).friction = (uniform(0.5, 1.5), 0.005, 1e-4)
    v.of(geom).mass = log_uniform(0.5, 2.0)
    v.of(geom).rgba = normal((0.5, 0.5, 0.5, 1.0), (0.1, 0.1, 0.1, 0.0))
    v.of(geom).type = choice(["box", "ellipsoid"])  # keywords: the setter's literals
    v.of(geom).condim = choice([1, 3, 4])
    v.of(joint).damping = uniform(0, 2)  # ints where reals go, as for a value
    v.of(joint).type = choice(("hinge", "slide"))
    assert_type(v.of(geom).type, mjcf.GeomType | None)  # reading: the element's own value
    assert v.of(geom).type == "box"
    assert len(v) == 7  # friction twice: the second replaces the first

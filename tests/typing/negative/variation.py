"""Distributions that do not fit the attribute they are stated on (Variation.of() is typed
as the element, so its setters check them as they check a value)."""

import typed_mjcf as mjcf
from typed_mjcf.variation import Variation, choice, normal, uniform

model = mjcf.RootElement()
geom = model.worldbody.add_geom(size=(0.1,))
v = Variation()

# the wrong number of values: pos takes 3, friction 1 to 3 (so a 2-vector fits friction)
v.of(geom).pos = uniform((0, 0), (1, 1))  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
v.of(geom).friction = uniform((0.5, 0, 0, 0), (1.5, 0, 0, 0))  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
v.of(geom).rgba = (uniform(0.0, 1.0), 0.5, 1.0)  # E: mypy[assignment] pyright[reportAttributeAccessIssue]

# a number for a keyword, a word outside the keyword set, a float for an integer
v.of(geom).type = uniform(0.0, 1.0)  # E: mypy[arg-type] pyright[reportAttributeAccessIssue]
v.of(geom).type = choice(["box", "spher"])  # E: mypy[list-item] pyright[reportAttributeAccessIssue]
v.of(geom).contype = normal(1.0, 0.5)  # E: mypy[assignment] pyright[reportAttributeAccessIssue]

# a name the element does not have
v.of(geom).frictoin = uniform(0.5, 1.5)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue]

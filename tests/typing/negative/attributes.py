"""Keyword arguments of add_<tag>(), insert() and add() that the grammar refuses."""

import numpy as np

import typed_mjcf as mjcf

model = mjcf.RootElement(modl="arm")  # E: mypy[call-arg] pyright[reportCallIssue]
body = model.worldbody.add_body(name="arm")

# a misspelt attribute
body.add_geom(tpye="capsule")  # E: mypy[call-arg] pyright[reportCallIssue]
body.add_joint(nme="shoulder")  # E: mypy[call-arg] pyright[reportCallIssue]

# a keyword outside the grammar's set
body.add_geom(type="capsul")  # E: mypy[arg-type] pyright[reportArgumentType]
body.add_joint(type="hinged")  # E: mypy[arg-type] pyright[reportArgumentType]
model.add_compiler(angle="radians")  # E: mypy[arg-type] pyright[reportArgumentType]
# a keyword of a list another tag shares that MuJoCo refuses on this tag (a site is no plane)
body.add_site(type="plane")  # E: mypy[arg-type] pyright[reportArgumentType]
body.add_site().type = "hfield"  # E: mypy[assignment] pyright[reportAttributeAccessIssue]

# a keyword-valued boolean ("false" / "true" / "auto", or a bool) given another word
body.add_joint(limited="yes")  # E: mypy[arg-type] pyright[reportArgumentType]

# arrays of the wrong length: fixed (pos: 3) and ranged (size: 1 to 3)
body.add_geom(pos=(1, 2))  # E: mypy[arg-type] pyright[reportArgumentType]
body.add_geom(rgba=(1, 0, 0))  # E: mypy[arg-type] pyright[reportArgumentType]
body.add_geom(size=(1, 2, 3, 4))  # E: mypy[arg-type] pyright[reportArgumentType]
body.add_geom(size=())  # E: mypy[arg-type] pyright[reportArgumentType]

# strings where numbers belong, floats where integers belong
body.add_geom(mass="heavy")  # E: mypy[arg-type] pyright[reportArgumentType]
body.add_geom(pos=("0", "0", "1"))  # E: mypy[arg-type] pyright[reportArgumentType]
body.add_geom(condim=3.5)  # E: mypy[arg-type] pyright[reportArgumentType]
model.asset.add_mesh(face=(0.5, 1, 2))  # E: mypy[arg-type] pyright[reportArgumentType]
model.asset.add_mesh(face=np.array([0.5, 1, 2], dtype=np.float64))  # E: mypy[arg-type] pyright[reportArgumentType]

# a number where a string or a bool belongs
body.add_geom(name=3)  # E: mypy[arg-type] pyright[reportArgumentType]
model.compiler.autolimits = "true"  # E: mypy[assignment] pyright[reportAttributeAccessIssue]

# numpy arrays are not scalars, even of one element; bools are not keywords for a class
body.add_geom(mass=np.zeros(1))  # E: mypy[arg-type] pyright[reportArgumentType]
body.add_geom(dclass=3)  # E: mypy[arg-type] pyright[reportArgumentType]
body.add_geom(dclass=body)  # E: mypy[arg-type] pyright[reportArgumentType]
body.add_geom(pos=[0, 0, "1"])  # E: mypy[list-item] pyright[reportArgumentType]

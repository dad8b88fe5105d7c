"""References given an element of the wrong namespace, and look-up results."""

from collections.abc import Sequence

import typed_mjcf as mjcf

model = mjcf.RootElement()
body = model.worldbody.add_body(name="arm")
joint = body.add_joint(name="shoulder")
geom = body.add_geom(name="upper")
material = model.asset.add_material(name="steel")
texture = model.asset.add_texture(name="checker", builtin="checker")

model.sensor.add_jointpos(joint=geom)  # E: mypy[arg-type] pyright[reportArgumentType]
model.actuator.add_motor(joint=body)  # E: mypy[arg-type] pyright[reportArgumentType]
geom.material = texture  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
material.texture = material  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
model.sensor.add_touch(site=3)  # E: mypy[arg-type] pyright[reportArgumentType]

# find() may return None, and returns the classes of that namespace only
print(model.find("joint", "shoulder").name)  # E: mypy[union-attr] pyright[reportOptionalMemberAccess]
found: mjcf.Geom | None = model.find("joint", "shoulder")  # E: mypy[assignment] pyright[reportAssignmentType]
geoms: Sequence[mjcf.Body] = model.find_all("geom")  # E: mypy[assignment] pyright[reportAssignmentType]

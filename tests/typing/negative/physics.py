"""Binding elements to a physics: each kind has the arrays MuJoCo has for it, no others."""

import numpy as np
import numpy.typing as npt

import typed_mjcf as mjcf

model = mjcf.RootElement()
body = model.worldbody.add_body(name="arm")
joint = body.add_joint(name="shoulder")
geom = body.add_geom(name="upper", size=(0.1,))
site = body.add_site(name="tip")
camera = body.add_camera(name="eye")
light = body.add_light(name="lamp")
motor = model.actuator.add_motor(name="m", joint=joint)
sensor = model.sensor.add_jointpos(name="angle", joint=joint)
tendon = model.tendon.add_fixed(name="t")
physics = mjcf.Physics.from_mjcf_model(model)

# an array of another kind of element
print(physics.bind(geom).qpos)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
print(physics.bind(joint).rgba)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
print(physics.bind(body).ctrl)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
print(physics.bind(site).qvel)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
print(physics.bind(camera).sensordata)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
print(physics.bind(light).gear)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
print(physics.bind(motor).xpos)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
print(physics.bind(sensor).qpos)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
physics.bind(tendon).rgba = (1, 0, 0)  # ok: tendons have rgba
print(physics.bind(tendon).xpos)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
print(physics.bind([joint, joint]).qpso)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]

# arrays keep their dtype: a geom's rgba is float32, its contype int32
rgba: npt.NDArray[np.float64] = physics.bind(geom).rgba  # E: mypy[assignment] pyright[reportAssignmentType]
contype: npt.NDArray[np.float64] = physics.bind(geom).contype  # E: mypy[assignment] pyright[reportAssignmentType]

# an element of no kind MuJoCo compiles gives the untyped binding: no arrays to see
print(physics.bind(model.compiler).qpos)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]

# named indexers: a misspelt array
print(physics.named.data.qpso["shoulder"])  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]

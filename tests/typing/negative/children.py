"""Children the grammar does not allow under their parent."""

import typed_mjcf as mjcf

model = mjcf.RootElement()
body = model.worldbody.add_body(name="arm")
joint = body.add_joint(name="shoulder")

model.worldbody.add_motor(name="m")  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType]
joint.add_geom()  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType]
model.add_body()  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType]
model.actuator.add_joint()  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType]
print(body.motor)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]

# a child list is a list of that class only
first_joint: mjcf.Geom = body.joint[0]  # E: mypy[assignment] pyright[reportAssignmentType]

"""Reading and assigning attributes as properties."""

import typed_mjcf as mjcf

model = mjcf.RootElement()
body = model.worldbody.add_body(name="arm")
joint = body.add_joint(name="shoulder")
geom = body.add_geom(name="upper")

# a misspelt property, read and written
print(joint.tpye)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
joint.tpye = "hinge"  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue]
geom.rbga = (1, 0, 0, 1)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue]

# values the grammar refuses
joint.type = "hinged"  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
joint.limited = "yes"  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
geom.size = (1, 2, 3, 4)  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
geom.rgba = (1, 0, 0)  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
geom.mass = "heavy"  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
geom.condim = 3.5  # E: mypy[assignment] pyright[reportAttributeAccessIssue]

# flags that also take one keyword alone: a word of neither set, or one that goes alone
model.worldbody.add_body().add_joint(name="j")
pid = model.actuator.add_pid(joint="j")
pid.input = "bogus"  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
pid.input = ("pos", "expmap")  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
pid.input = "pos ff"  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
model.actuator.add_general(input="nnoe")  # E: mypy[arg-type] pyright[reportArgumentType]
chart: mjcf.InputbitAlone = "pos"  # E: mypy[assignment] pyright[reportAssignmentType]

# a getter returns what is stored: an array (not the tuple given), or None when unset
fresh = body.add_geom()
size: tuple[float, float] = fresh.size  # E: mypy[assignment] pyright[reportAssignmentType]
mass: float = fresh.mass  # E: mypy[assignment] pyright[reportAssignmentType]
joint_type: str = body.add_joint().type  # E: mypy[assignment] pyright[reportAssignmentType]

# child properties are read-only: add or remove children instead
body.geom = body.geom  # E: mypy[misc] pyright[reportAttributeAccessIssue]
model.compiler = model.compiler  # E: mypy[misc] pyright[reportAttributeAccessIssue]

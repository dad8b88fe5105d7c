"""Mistakes in ordinary mujoco code that the generated stubs make both checkers report.

Checked by tests/typing/test_mujoco_stubs.py, line by line (markers as in negative/).
"""

import mujoco
import numpy as np

m = mujoco.MjModel.from_xml_string("<mujoco/>")
d = mujoco.MjData(m)

# calls: argument count, argument types, names that do not exist
mujoco.mj_step(m)  # E: mypy[call-arg] pyright[reportCallIssue]
mujoco.mj_step(m, d, 2.5)  # E: mypy[arg-type] pyright[reportArgumentType]
mujoco.mj_name2id(m, "body", "torso")  # E: mypy[arg-type] pyright[reportArgumentType]
mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, 3)  # E: mypy[arg-type] pyright[reportArgumentType]
mujoco.mj_stepp(m, d)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType]
mujoco.mj_forward(d, m)  # E: mypy[arg-type] pyright[reportArgumentType]
mujoco.MjData()  # E: mypy[call-arg] pyright[reportCallIssue]

# fields: misspelt, on the wrong struct, read-only, wrong type
print(d.qpso)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
print(m.body("torso").xpos)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]
m.nq = 3  # E: mypy[misc] pyright[reportAttributeAccessIssue]
m.opt.timestep = "fast"  # E: mypy[assignment] pyright[reportAttributeAccessIssue]
print(mujoco.mjtObj.mjOBJ_BODDY)  # E: mypy[attr-defined] pyright[reportAttributeAccessIssue,reportUnknownMemberType,reportUnknownArgumentType]

# arrays MuJoCo writes into must be arrays of its dtype; inputs must not be scalars
jacp32 = np.zeros((3, m.nv), dtype=np.float32)
mujoco.mj_jacBody(m, d, [0.0, 0.0, 0.0], None, 0)  # E: mypy[arg-type] pyright[reportArgumentType]
mujoco.mj_jacBody(m, d, jacp32, None, 0)  # E: mypy[arg-type] pyright[reportArgumentType]
mujoco.mju_add3(np.zeros(3), 1.0, [1, 2, 3])  # E: mypy[arg-type] pyright[reportArgumentType]

# MjSpec: keywords are checked, compile() gives an MjModel
spec = mujoco.MjSpec()
spec.worldbody.add_body(nmae="torso")  # E: mypy[call-arg] pyright[reportCallIssue]
spec.worldbody.add_geom(type="sphere")  # E: mypy[arg-type] pyright[reportArgumentType]
data: mujoco.MjData = spec.compile()  # E: mypy[assignment] pyright[reportAssignmentType]
spec.to_xml(pretty=True)  # E: mypy[call-arg] pyright[reportCallIssue]

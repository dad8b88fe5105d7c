"""What an editor costs: pyright's language server on authoring scripts, three libraries.

Run from the repository root (not collected by pytest; ``nox -s bench_editor`` runs it)::

    python -m tests.bench.editor                 # 3 rounds, interleaved, medians
    python -m tests.bench.editor --rounds 1 --libs typed

For each library (typed-mjcf, dm_control.mjcf, mujoco.MjSpec) a fresh
``pyright-langserver --stdio`` (the engine of VS Code's Pylance) gets three authoring scripts,
the way an editor sends them: open a file, ask for a completion, then for each later cursor
position one edit (the whole text again, as a new version) and one completion. Per library:

- first completion after opening a file: server CPU time (user + system of the server and
  its children, from ``/proc/<pid>/stat``) from ``didOpen`` until the server is idle again;
- each later edit + request: the same, per request (median and 90th percentile);
- server memory (RSS of the server's processes): after the first completion (cold) and after
  the long session (every script, every position, ``--session`` times over);
- completion hits: positions whose expected item is offered.

The workspace is a temporary folder with no configuration, so the libraries are read as
installed packages (as a user's project reads them), with this interpreter's environment.
A report, not a test: nothing here asserts a time.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import statistics
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from tests.lsp import LanguageServer

TIMEOUT = 600.0  # a loaded machine answers slowly; CPU time is what is measured
TICK = os.sysconf("SC_CLK_TCK")
PAGE = os.sysconf("SC_PAGE_SIZE")
MARK = re.compile(r"\$\{([^}]*)\}")  # ${expected}: a cursor position and the item expected

# ---------------------------------------------------------------------------- the scripts
# Each ${label} is a cursor position; the completion there should offer ``label``.

TYPED = [
    '''\
import typed_mjcf as mjcf

model = mjcf.RootElement(model="walker")
model.option.${timestep}timestep = 0.002
model.compiler.${angle}angle = "${radian}radian"
torso = model.worldbody.${add_body}add_body(name="torso", pos=(0, 0, 1.2))
torso.${add_freejoint}add_freejoint()
torso.add_geom(${type}type="${capsule}capsule", size=(0.07, 0.3), ${rgba}rgba=(0.8, 0.6, 0.4, 1))
for side in ("left", "right"):
    thigh = torso.add_body(name=f"{side}_thigh", pos=(0, 0.1, -0.3))
    thigh.${add_joint}add_joint(name=f"{side}_hip", type="${hinge}hinge", axis=(0, 1, 0), ${range}range=(-1.5, 0.5))
    thigh.${add_geom}add_geom(type="capsule", ${fromto}fromto=(0, 0, 0, 0, 0, -0.45), size=(0.05,))
    shin = thigh.add_body(name=f"{side}_shin", pos=(0, 0, -0.45))
    shin.add_joint(name=f"{side}_knee", type="hinge", ${axis}axis=(0, 1, 0), ${damping}damping=0.5)
    shin.add_geom(type="${cylinder}capsule", fromto=(0, 0, 0, 0, 0, -0.4), size=(0.04,))
    foot = shin.${add_site}add_site(name=f"{side}_foot", pos=(0, 0, -0.4))
    model.actuator.${add_motor}add_motor(name=f"{side}_hip_motor", ${joint}joint=f"{side}_hip", ${gear}gear=(100,))
    model.actuator.add_position(name=f"{side}_knee_servo", joint=f"{side}_knee", ${kp}kp=50.0)
    model.sensor.${add_touch}add_touch(${site}site=foot)
    model.sensor.add_jointpos(${joint}joint=f"{side}_knee")
light = model.worldbody.add_light(${directional}directional=True, ${diffuse}diffuse=(0.8, 0.8, 0.8))
floor = model.worldbody.add_geom(type="${plane}plane", size=(10, 10, 0.1), ${condim}condim=3)
xml = model.${to_xml_string}to_xml_string()
''',
    '''\
import typed_mjcf as mjcf

arm = mjcf.RootElement(model="arm")
arm.default.${add_default}add_default(class_="link")
link = arm.default.default[0]
link.geom.${contype}contype = 1
link.joint.${armature}armature = 0.1
base = arm.worldbody.add_body(name="base", ${childclass}childclass="link")
base.add_geom(type="${box}box", size=(0.1, 0.1, 0.05), ${mass}mass=2.0)
upper = base.add_body(name="upper", pos=(0, 0, 0.1))
upper.add_joint(name="shoulder", ${type}type="hinge", axis=(0, 0, 1), ${limited}limited=True)
upper.add_geom(type="capsule", fromto=(0, 0, 0, 0.3, 0, 0), size=(0.03,), ${friction}friction=(1.0,))
upper.${add_inertial}add_inertial(pos=(0.15, 0, 0), mass=0.5, ${diaginertia}diaginertia=(0.01, 0.01, 0.001))
fore = upper.add_body(name="fore", pos=(0.3, 0, 0))
elbow = fore.add_joint(name="elbow", type="hinge", axis=(0, 0, 1))
fore.add_geom(type="capsule", fromto=(0, 0, 0, 0.25, 0, 0), size=(0.025,))
tip = fore.add_site(name="tip", pos=(0.25, 0, 0), ${size}size=(0.01,))
tendon = arm.tendon.${add_fixed}add_fixed(name="coupling")
tendon.${add_joint}add_joint(joint=elbow, ${coef}coef=1.0)
arm.actuator.${add_general}add_general(name="g", joint="shoulder", ${gainprm}gainprm=(1.0,), ${biastype}biastype="${affine}affine")
arm.actuator.add_motor(name="m", ${tendon}tendon="coupling")
arm.sensor.${add_framepos}add_framepos(${objtype}objtype="${site}site", objname=tip)
arm.sensor.add_jointvel(joint=elbow, ${noise}noise=0.01)
eq = arm.equality.${add_weld}add_weld(body1="fore", ${solref}solref=(0.02, 1.0))
key = arm.keyframe.${add_key}add_key(name="home", ${qpos}qpos=(0.0, 0.0))
found = arm.${find}find("joint", "elbow")
''',
    '''\
import typed_mjcf as mjcf

scene = mjcf.RootElement(model="scene")
tex = scene.asset.${add_texture}add_texture(name="grid", type="${2d}2d", ${builtin}builtin="${checker}checker", width=512, height=512)
mat = scene.asset.${add_material}add_material(name="grid", ${texture}texture=tex, ${texrepeat}texrepeat=(4, 4))
mesh = scene.asset.${add_mesh}add_mesh(name="bunny", ${file}file="bunny.stl", ${scale}scale=(1, 1, 1))
hf = scene.asset.${add_hfield}add_hfield(name="terrain", nrow=10, ncol=10, size=(5, 5, 1, 0.1))
scene.visual.${headlight}headlight.ambient = (0.3, 0.3, 0.3)
scene.visual.quality.${shadowsize}shadowsize = 4096
scene.option.${gravity}gravity = (0, 0, -9.81)
scene.option.${integrator}integrator = "${RK4}RK4"
scene.worldbody.add_geom(type="${hfield}hfield", ${hfield}hfield=hf, ${material}material=mat)
cam = scene.worldbody.${add_camera}add_camera(name="top", pos=(0, 0, 5), ${mode}mode="${fixed}fixed")
obj = scene.worldbody.add_body(name="bunny", pos=(0, 0, 1))
obj.${add_freejoint}add_freejoint(name="free")
obj.add_geom(type="mesh", ${mesh}mesh=mesh, ${density}density=500.0)
rep = scene.worldbody.${add_replicate}add_replicate(${count}count=4, ${offset}offset=(0.5, 0, 0))
rep.add_geom(type="sphere", size=(0.05,))
frame = scene.worldbody.${add_frame}add_frame(pos=(1, 0, 0))
frame.add_site(name="mark", ${type}type="${sphere}sphere")
scene.contact.${add_exclude}add_exclude(body1="bunny", ${body2}body2="world")
scene.${compile}compile()
''',
]

DM_CONTROL = [
    '''\
from dm_control import mjcf

model = mjcf.RootElement(model="walker")
model.option.${timestep}timestep = 0.002
model.compiler.${angle}angle = "${radian}radian"
torso = model.worldbody.${add}add("body", name="torso", pos=(0, 0, 1.2))
torso.${add}add("freejoint")
torso.add("geom", ${type}type="${capsule}capsule", size=(0.07, 0.3), ${rgba}rgba=(0.8, 0.6, 0.4, 1))
for side in ("left", "right"):
    thigh = torso.add("body", name=f"{side}_thigh", pos=(0, 0.1, -0.3))
    thigh.${add}add("joint", name=f"{side}_hip", type="${hinge}hinge", axis=(0, 1, 0), ${range}range=(-1.5, 0.5))
    thigh.${add}add("geom", type="capsule", ${fromto}fromto=(0, 0, 0, 0, 0, -0.45), size=(0.05,))
    shin = thigh.add("body", name=f"{side}_shin", pos=(0, 0, -0.45))
    shin.add("joint", name=f"{side}_knee", type="hinge", ${axis}axis=(0, 1, 0), ${damping}damping=0.5)
    shin.add("geom", type="${cylinder}capsule", fromto=(0, 0, 0, 0, 0, -0.4), size=(0.04,))
    foot = shin.${add}add("site", name=f"{side}_foot", pos=(0, 0, -0.4))
    model.actuator.${add}add("motor", name=f"{side}_hip_motor", ${joint}joint=f"{side}_hip", ${gear}gear=(100,))
    model.actuator.add("position", name=f"{side}_knee_servo", joint=f"{side}_knee", ${kp}kp=50.0)
    model.sensor.${add}add("touch", ${site}site=foot)
    model.sensor.add("jointpos", ${joint}joint=f"{side}_knee")
light = model.worldbody.add("light", ${directional}directional=True, ${diffuse}diffuse=(0.8, 0.8, 0.8))
floor = model.worldbody.add("geom", type="${plane}plane", size=(10, 10, 0.1), ${condim}condim=3)
xml = model.${to_xml_string}to_xml_string()
''',
    '''\
from dm_control import mjcf

arm = mjcf.RootElement(model="arm")
arm.default.${add}add("default", dclass="link")
link = arm.default.default[0]
link.geom.${contype}contype = 1
link.joint.${armature}armature = 0.1
base = arm.worldbody.add("body", name="base", ${childclass}childclass="link")
base.add("geom", type="${box}box", size=(0.1, 0.1, 0.05), ${mass}mass=2.0)
upper = base.add("body", name="upper", pos=(0, 0, 0.1))
upper.add("joint", name="shoulder", ${type}type="hinge", axis=(0, 0, 1), ${limited}limited=True)
upper.add("geom", type="capsule", fromto=(0, 0, 0, 0.3, 0, 0), size=(0.03,), ${friction}friction=(1.0,))
upper.${add}add("inertial", pos=(0.15, 0, 0), mass=0.5, ${diaginertia}diaginertia=(0.01, 0.01, 0.001))
fore = upper.add("body", name="fore", pos=(0.3, 0, 0))
elbow = fore.add("joint", name="elbow", type="hinge", axis=(0, 0, 1))
fore.add("geom", type="capsule", fromto=(0, 0, 0, 0.25, 0, 0), size=(0.025,))
tip = fore.add("site", name="tip", pos=(0.25, 0, 0), ${size}size=(0.01,))
tendon = arm.tendon.${add}add("fixed", name="coupling")
tendon.${add}add("joint", joint=elbow, ${coef}coef=1.0)
arm.actuator.${add}add("general", name="g", joint="shoulder", ${gainprm}gainprm=(1.0,), ${biastype}biastype="${affine}affine")
arm.actuator.add("motor", name="m", ${tendon}tendon="coupling")
arm.sensor.${add}add("framepos", ${objtype}objtype="${site}site", objname=tip)
arm.sensor.add("jointvel", joint=elbow, ${noise}noise=0.01)
eq = arm.equality.${add}add("weld", body1="fore", ${solref}solref=(0.02, 1.0))
key = arm.keyframe.${add}add("key", name="home", ${qpos}qpos=(0.0, 0.0))
found = arm.${find}find("joint", "elbow")
''',
    '''\
from dm_control import mjcf

scene = mjcf.RootElement(model="scene")
tex = scene.asset.${add}add("texture", name="grid", type="${2d}2d", ${builtin}builtin="${checker}checker", width=512, height=512)
mat = scene.asset.${add}add("material", name="grid", ${texture}texture=tex, ${texrepeat}texrepeat=(4, 4))
mesh = scene.asset.${add}add("mesh", name="bunny", ${file}file="bunny.stl", ${scale}scale=(1, 1, 1))
hf = scene.asset.${add}add("hfield", name="terrain", nrow=10, ncol=10, size=(5, 5, 1, 0.1))
scene.visual.${headlight}headlight.ambient = (0.3, 0.3, 0.3)
scene.visual.quality.${shadowsize}shadowsize = 4096
scene.option.${gravity}gravity = (0, 0, -9.81)
scene.option.${integrator}integrator = "${RK4}RK4"
scene.worldbody.add("geom", type="${hfield}hfield", ${hfield}hfield=hf, ${material}material=mat)
cam = scene.worldbody.${add}add("camera", name="top", pos=(0, 0, 5), ${mode}mode="${fixed}fixed")
obj = scene.worldbody.add("body", name="bunny", pos=(0, 0, 1))
obj.${add}add("freejoint", name="free")
obj.add("geom", type="mesh", ${mesh}mesh=mesh, ${density}density=500.0)
rep = scene.worldbody.${add}add("replicate", ${count}count=4, ${offset}offset=(0.5, 0, 0))
rep.add("geom", type="sphere", size=(0.05,))
frame = scene.worldbody.${add}add("frame", pos=(1, 0, 0))
frame.add("site", name="mark", ${type}type="${sphere}sphere")
scene.contact.${add}add("exclude", body1="bunny", ${body2}body2="world")
scene.${to_xml_string}to_xml_string()
''',
]

MJSPEC = [
    '''\
import mujoco

spec = mujoco.MjSpec()
spec.modelname = "walker"
spec.option.${timestep}timestep = 0.002
spec.compiler.${degree}degree = False
torso = spec.worldbody.${add_body}add_body(name="torso", pos=[0, 0, 1.2])
torso.${add_freejoint}add_freejoint()
torso.add_geom(${type}type=mujoco.mjtGeom.${mjGEOM_CAPSULE}mjGEOM_CAPSULE, size=[0.07, 0.3, 0], ${rgba}rgba=[0.8, 0.6, 0.4, 1])
for side in ("left", "right"):
    thigh = torso.add_body(name=f"{side}_thigh", pos=[0, 0.1, -0.3])
    thigh.${add_joint}add_joint(name=f"{side}_hip", type=mujoco.mjtJoint.${mjJNT_HINGE}mjJNT_HINGE, axis=[0, 1, 0], ${range}range=[-1.5, 0.5])
    thigh.${add_geom}add_geom(type=mujoco.mjtGeom.mjGEOM_CAPSULE, ${fromto}fromto=[0, 0, 0, 0, 0, -0.45], size=[0.05, 0, 0])
    shin = thigh.add_body(name=f"{side}_shin", pos=[0, 0, -0.45])
    shin.add_joint(name=f"{side}_knee", type=mujoco.mjtJoint.mjJNT_HINGE, ${axis}axis=[0, 1, 0], ${damping}damping=[0.5])
    shin.add_geom(type=mujoco.mjtGeom.${mjGEOM_CYLINDER}mjGEOM_CAPSULE, fromto=[0, 0, 0, 0, 0, -0.4], size=[0.04, 0, 0])
    foot = shin.${add_site}add_site(name=f"{side}_foot", pos=[0, 0, -0.4])
    motor = spec.${add_actuator}add_actuator(name=f"{side}_hip_motor", ${target}target=f"{side}_hip", ${gear}gear=[100, 0, 0, 0, 0, 0])
    motor.${trntype}trntype = mujoco.mjtTrn.mjTRN_JOINT
    spec.${add_sensor}add_sensor(name=f"{side}_touch", ${objname}objname=f"{side}_foot")
light = spec.worldbody.${add_light}add_light(${diffuse}diffuse=[0.8, 0.8, 0.8])
floor = spec.worldbody.add_geom(type=mujoco.mjtGeom.${mjGEOM_PLANE}mjGEOM_PLANE, size=[10, 10, 0.1], ${condim}condim=3)
xml = spec.${to_xml}to_xml()
''',
    '''\
import mujoco

arm = mujoco.MjSpec()
link = arm.${add_default}add_default("link", arm.default)
link.geom.${contype}contype = 1
link.joint.${armature}armature = 0.1
base = arm.worldbody.add_body(name="base", ${childclass}childclass="link")
base.add_geom(type=mujoco.mjtGeom.${mjGEOM_BOX}mjGEOM_BOX, size=[0.1, 0.1, 0.05], ${mass}mass=2.0)
upper = base.add_body(name="upper", pos=[0, 0, 0.1])
upper.add_joint(name="shoulder", ${type}type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0, 0, 1], ${limited}limited=mujoco.mjtLimited.mjLIMITED_TRUE)
upper.add_geom(type=mujoco.mjtGeom.mjGEOM_CAPSULE, fromto=[0, 0, 0, 0.3, 0, 0], size=[0.03, 0, 0], ${friction}friction=[1.0, 0.005, 0.0001])
upper.${explicitinertial}explicitinertial = True
fore = upper.add_body(name="fore", pos=[0.3, 0, 0])
elbow = fore.add_joint(name="elbow", type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0, 0, 1])
fore.add_geom(type=mujoco.mjtGeom.mjGEOM_CAPSULE, fromto=[0, 0, 0, 0.25, 0, 0], size=[0.025, 0, 0])
tip = fore.add_site(name="tip", pos=[0.25, 0, 0], ${size}size=[0.01, 0, 0])
tendon = arm.${add_tendon}add_tendon(name="coupling")
tendon.${wrap_joint}wrap_joint("elbow", 1.0)
act = arm.add_actuator(name="g", target="shoulder", ${gainprm}gainprm=[1.0] + [0.0] * 9)
act.${biastype}biastype = mujoco.mjtBias.${mjBIAS_AFFINE}mjBIAS_AFFINE
arm.add_actuator(name="m", target="coupling", ${trntype}trntype=mujoco.mjtTrn.mjTRN_TENDON)
sens = arm.add_sensor(name="tip_pos", ${type}type=mujoco.mjtSensor.mjSENS_FRAMEPOS, objname="tip")
sens.${objtype}objtype = mujoco.mjtObj.${mjOBJ_SITE}mjOBJ_SITE
arm.add_sensor(name="elbow_vel", type=mujoco.mjtSensor.mjSENS_JOINTVEL, objname="elbow", ${noise}noise=0.01)
eq = arm.${add_equality}add_equality(name1="fore", ${solref}solref=[0.02, 1.0])
key = arm.${add_key}add_key(name="home", ${qpos}qpos=[0.0, 0.0])
found = arm.${joint}joint("elbow")
''',
    '''\
import mujoco

scene = mujoco.MjSpec()
tex = scene.${add_texture}add_texture(name="grid", type=mujoco.mjtTexture.${mjTEXTURE_2D}mjTEXTURE_2D, ${builtin}builtin=mujoco.mjtBuiltin.mjBUILTIN_CHECKER, width=512, height=512)
mat = scene.${add_material}add_material(name="grid", ${texrepeat}texrepeat=[4, 4])
mesh = scene.${add_mesh}add_mesh(name="bunny", ${file}file="bunny.stl", ${scale}scale=[1, 1, 1])
hf = scene.${add_hfield}add_hfield(name="terrain", nrow=10, ncol=10, size=[5, 5, 1, 0.1])
scene.visual.${headlight}headlight.ambient = [0.3, 0.3, 0.3]
scene.visual.quality.${shadowsize}shadowsize = 4096
scene.option.${gravity}gravity = [0, 0, -9.81]
scene.option.${integrator}integrator = mujoco.mjtIntegrator.${mjINT_RK4}mjINT_RK4
scene.worldbody.add_geom(type=mujoco.mjtGeom.${mjGEOM_HFIELD}mjGEOM_HFIELD, ${hfieldname}hfieldname="terrain", ${material}material="grid")
cam = scene.worldbody.${add_camera}add_camera(name="top", pos=[0, 0, 5], ${mode}mode=mujoco.mjtCamLight.mjCAMLIGHT_FIXED)
obj = scene.worldbody.add_body(name="bunny", pos=[0, 0, 1])
obj.${add_freejoint}add_freejoint(name="free")
obj.add_geom(type=mujoco.mjtGeom.mjGEOM_MESH, ${meshname}meshname="bunny", ${density}density=500.0)
frame = scene.worldbody.${add_frame}add_frame(pos=[1, 0, 0])
frame.add_site(name="mark", ${type}type=mujoco.mjtGeom.${mjGEOM_SPHERE}mjGEOM_SPHERE)
scene.${add_exclude}add_exclude(${bodyname2}bodyname2="world")
model = scene.${compile}compile()
''',
]

LIBRARIES = {"typed": ("typed-mjcf", TYPED), "dm_control": ("dm_control.mjcf", DM_CONTROL),
             "mjspec": ("mujoco.MjSpec", MJSPEC)}


@dataclass(frozen=True)
class Script:
    text: str
    cursors: list[tuple[int, int, str]]  # line, character, expected label


def parse_script(marked: str) -> Script:
    """The text without its ``${label}`` marks, and each mark's position and label: the
    word after a mark is there already, and the cursor is one character into it (what an
    editor asks as the user starts typing the word)."""
    text, last = "", 0
    cursors: list[tuple[int, int, str]] = []
    for match in MARK.finditer(marked):
        text += marked[last:match.start()]
        line = text.count("\n")
        # one character typed: the cursor is just after the first letter of the word
        cursors.append((line, len(text) - (text.rfind("\n") + 1) + 1, match[1]))
        last = match.end()
    return Script(text + marked[last:], cursors)


def typing_at(text: str, line: int, character: int) -> str:
    """The script as the user has it while typing at (line, character): that line ends at
    the cursor, its open brackets and quote closed (as an editor's auto-closing leaves it)."""
    lines = text.split("\n")
    typed = lines[line][:character]
    closers: list[str] = []
    quoted = False
    for char in typed:
        if char == '"':
            quoted = not quoted
        elif not quoted and char in "([{":
            closers.append({"(": ")", "[": "]", "{": "}"}[char])
        elif not quoted and char in ")]}" and closers:
            closers.pop()
    lines[line] = typed + ('"' if quoted else "") + "".join(reversed(closers))
    return "\n".join(lines)


# ---------------------------------------------------------------------------- the server


def _descendants(root: int) -> list[int]:
    """``root`` and every process below it (the Python launcher, node, node's workers)."""
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                stat = Path(f"/proc/{entry}/stat").read_text()
            except OSError:
                continue
            parent = int(stat[stat.rindex(")") + 2:].split()[1])
            children.setdefault(parent, []).append(int(entry))
    found: list[int] = []
    todo = [root]
    while todo:
        pid = todo.pop()
        found.append(pid)
        todo += children.get(pid, [])
    return found


def _cpu_and_rss(root: int) -> tuple[float, int]:
    """Seconds of CPU (user + system, own and waited-for children) and bytes resident."""
    ticks = pages = 0
    for pid in _descendants(root):
        try:
            fields = Path(f"/proc/{pid}/stat").read_text()
        except OSError:
            continue
        rest = fields[fields.rindex(")") + 2:].split()
        ticks += sum(int(x) for x in rest[11:15])  # utime stime cutime cstime
        pages += int(rest[21])  # rss
    return ticks / TICK, pages * PAGE


class Server(LanguageServer):
    """pyright-langserver, with the CPU and memory of its processes."""

    def __init__(self, root: Path) -> None:
        super().__init__(root, TIMEOUT)
        self.settle()

    def usage(self) -> tuple[float, int]:
        return _cpu_and_rss(self.pid)

    def settle(self, quiet: float = 0.15) -> None:
        """Wait until the server's processes use no CPU for ``quiet`` seconds (background
        checking of the open file counts toward the request that caused it)."""
        last, since = self.usage()[0], time.monotonic()
        while time.monotonic() - since < quiet:
            time.sleep(0.05)
            now = self.usage()[0]
            if now - last > 0.011:  # more than a tick
                last, since = now, time.monotonic()

    def labels(self, uri: str, line: int, character: int) -> list[str]:
        return [str(item["label"]) for item in self.completion(uri, line, character)]


# ---------------------------------------------------------------------------- one session


@dataclass
class Result:
    first: list[float] = field(default_factory=lambda: [])  # fresh server, seconds of CPU
    first_warm: list[float] = field(default_factory=lambda: [])  # the other scripts
    later: list[float] = field(default_factory=lambda: [])
    cold_rss: list[int] = field(default_factory=lambda: [])
    long_rss: list[int] = field(default_factory=lambda: [])
    hits: int = 0
    misses: list[str] = field(default_factory=lambda: [])
    positions: int = 0


def _hit(labels: list[str], expected: str) -> bool:
    return any(label.strip("\"'=") == expected for label in labels)


def session(scripts: list[str], workspace: Path, repeats: int, result: Result) -> None:
    """One fresh server: each script opened, completed at every position, edited in between;
    then the whole session again ``repeats - 1`` times (the long session)."""
    server = Server(workspace)
    try:
        for round_ in range(repeats):
            for number, marked in enumerate(scripts):
                script = parse_script(marked)
                path = workspace / f"script_{number}.py"
                uri = path.as_uri()
                for step, (line, character, expected) in enumerate(script.cursors):
                    before = server.usage()[0]
                    text = typing_at(script.text, line, character)
                    if step == 0:
                        server.open(path, text)
                    else:  # an edit: the whole text again, as a new version
                        server.change(uri, text, step + 1)
                    labels = server.labels(uri, line, character)
                    server.settle()
                    cpu, rss = server.usage()
                    if round_ == 0:
                        if not _hit(labels, expected):
                            result.misses.append(f"script {number} line {line + 1}: {expected}")
                        result.hits += _hit(labels, expected)
                        result.positions += 1
                        if step == 0 and number == 0:
                            result.first.append(cpu - before)
                            result.cold_rss.append(rss)
                        elif step == 0:
                            result.first_warm.append(cpu - before)
                        else:
                            result.later.append(cpu - before)
                server.close_document(uri)
        result.long_rss.append(server.usage()[1])
    finally:
        server.close()


def _quantile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))] if ordered else float("nan")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="pyright's language server on authoring "
                                     "scripts: typed-mjcf, dm_control.mjcf, mujoco.MjSpec")
    parser.add_argument("--rounds", type=int, default=3, help="fresh servers per library")
    parser.add_argument("--session", type=int, default=4,
                        help="times every script is gone through per server (long session)")
    parser.add_argument("--libs", default=",".join(LIBRARIES))
    parser.add_argument("--misses", action="store_true", help="list the positions missed")
    parser.add_argument("--json", type=Path, help="also write the raw numbers here")
    args = parser.parse_args(argv)
    libs = [lib for lib in args.libs.split(",") if lib]
    results = {lib: Result() for lib in libs}
    with tempfile.TemporaryDirectory(prefix="typed-mjcf-editor-") as folder:
        workspace = Path(folder)
        for _ in range(args.rounds):  # interleaved: load on the machine hits every library
            for lib in libs:
                session(LIBRARIES[lib][1], workspace, args.session, results[lib])
    mib = 1024 * 1024
    rows: list[tuple[str, Callable[[Result], str]]] = [
        ("completion hits", lambda r: f"{r.hits // args.rounds}/{r.positions // args.rounds}"),
        ("first completion after open, fresh server (CPU)",
         lambda r: f"{statistics.median(r.first):.2f} s"),
        ("first completion after open, next files (CPU)",
         lambda r: f"{statistics.median(r.first_warm):.2f} s"),
        ("each later edit + request (CPU, median)",
         lambda r: f"{statistics.median(r.later) * 1000:.0f} ms"),
        ("each later edit + request (CPU, p90)",
         lambda r: f"{_quantile(r.later, 0.9) * 1000:.0f} ms"),
        ("server memory, cold (RSS)", lambda r: f"{statistics.median(r.cold_rss) / mib:.0f} MiB"),
        ("server memory, long session (RSS)",
         lambda r: f"{statistics.median(r.long_rss) / mib:.0f} MiB"),
    ]
    names = [LIBRARIES[lib][0] for lib in libs]
    width = max(len(label) for label, _ in rows)
    print(f"{'':{width}} | " + " | ".join(f"{n:>16}" for n in names))
    for label, cell in rows:
        print(f"{label:{width}} | " + " | ".join(f"{cell(results[lib]):>16}" for lib in libs))
    print(f"({args.rounds} fresh servers per library, interleaved; {os.cpu_count()} CPUs; "
          f"load average {os.getloadavg()[0]:.1f})")
    if args.misses:
        for lib in libs:
            print(f"{LIBRARIES[lib][0]} missed:", *sorted(set(results[lib].misses)), sep="\n  ")
    if args.json:
        args.json.write_text(json.dumps({lib: vars(r) for lib, r in results.items()}, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

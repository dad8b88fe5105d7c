"""The workloads, written once per library: the same model, built the way each library's users
build it.

W1  N bodies in chains of 10 (``CHAIN``), each with a hinge joint, a capsule geom, a site, a
    motor on the joint and a jointpos sensor of it. Named: every element has a name. Unnamed:
    only the joints are named, since the motors and sensors refer to them and MJCF references
    are by name; dm_control is the exception: there the joints are unnamed too and referred to
    as elements, which is how its users leave them unnamed (it names them ``unnamed_joint_<i>``
    in the output, the quadratic path of its export). The motor refers to its joint by name,
    the sensor by element (both styles of the README); MjSpec and lxml take names only.
    Export is ``to_xml_string()`` (pretty printed); MjSpec's cheapest valid export is
    ``spec.to_xml()``, which compiles the spec itself (an explicit ``compile()`` first would
    only add time); raw lxml builds the tree with ``etree.SubElement`` (numbers formatted
    with ``str``) and writes it with ``etree.tostring(pretty_print=True)``.
W2  parse + export of MJCF text: dm_control's ``suite/humanoid_CMU.xml`` (from its path: it
    ``<include>``s three files of ``suite/common``) and W1's N=5,000 output (from a string).
    The lxml floor parses, splices the included files' children in place of ``<include>``
    and serialises.
W3  K copies of a 10-body arm model with a default class (its joints and geoms use it, ten
    motors refer to its joints), each attached at its own site of a world model, under its
    own scope, then the export. The lxml floor builds directly the XML that typed-mjcf
    writes for it.

Each library is an :class:`Adapter`; a workload is a pair of callables (make, export) so the
harness can time the two phases apart.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

CHAIN = 10  # bodies per kinematic chain in W1
ARM_LINKS = 10  # bodies per arm in W3
AXIS = (0, 1, 0)
LINK_POS = (0, 0, 0.1)
SITE_POS = (0, 0, 0.1)
SIZE = (0.02,)
FROMTO = (0, 0, 0, 0, 0, 0.1)
CTRLRANGE = (-1, 1)
RGBA = (0.8, 0.2, 0.2, 1)


def chain_pos(chain: int) -> tuple[float, float, float]:
    """Where chain ``chain`` of W1 starts: a grid of 100 columns."""
    return (0.5 * (chain % 100), 0.5 * (chain // 100), 0.0)


def mount_pos(k: int) -> tuple[float, float, float]:
    """Where arm ``k`` of W3 is attached."""
    return (0.5 * (k % 50), 0.5 * (k // 50), 0.0)


def humanoid_path() -> str:
    """dm_control's ``suite/humanoid_CMU.xml`` (found through the installed package)."""
    import importlib.util

    spec = importlib.util.find_spec("dm_control")
    if spec is None or not spec.submodule_search_locations:
        raise RuntimeError("dm_control is not installed: W2 needs its suite/humanoid_CMU.xml")
    return os.path.join(next(iter(spec.submodule_search_locations)), "suite", "humanoid_CMU.xml")


# The libraries, imported by Adapter.load() (so a missing one only drops its rows).
mjcf_t: Any = None
mjcf_d: Any = None
mujoco: Any = None
etree: Any = None

Make = Callable[[], Any]
Export = Callable[[Any], str]


@dataclass(frozen=True)
class Workload:
    """A timed pair: ``make()`` builds (or parses) the model, ``export(model)`` writes it."""

    make: Make
    export: Export
    # a workload run elsewhere (another build's child process, tests/bench/builds.py):
    # remote(text wanted) -> (the run's Sample fields, timed there; the text written)
    remote: Callable[[bool], tuple[dict[str, float], str]] | None = None


class Adapter:
    """One library's versions of the workloads."""

    key = ""  # command-line name
    title = ""  # table name

    def available(self) -> str | None:
        """``None`` if usable, else why not."""
        try:
            self.load()
        except ImportError as error:
            return f"not installed ({error})"
        return None

    def load(self) -> None:
        raise NotImplementedError

    def version(self) -> str:
        raise NotImplementedError

    # W1 -------------------------------------------------------------------------------
    def w1_apis(self) -> tuple[str, ...]:
        return ("",)

    def w1(self, n: int, named: bool, api: str) -> Workload:
        raise NotImplementedError

    # W2 -------------------------------------------------------------------------------
    def w2_path(self, path: str) -> Workload:
        raise NotImplementedError

    def w2_text(self, text: str) -> Workload:
        raise NotImplementedError

    # W3 -------------------------------------------------------------------------------
    def w3(self, k: int) -> Workload:
        raise NotImplementedError


# =============================================================================== typed-mjcf


class TypedMjcf(Adapter):
    key = "typed"
    title = "typed-mjcf"

    def load(self) -> None:
        global mjcf_t
        import typed_mjcf as mjcf_t

    def version(self) -> str:
        return str(mjcf_t.__version__)

    def w1_apis(self) -> tuple[str, ...]:
        return ("add_<tag>()", 'add("<tag>")')

    def w1(self, n: int, named: bool, api: str) -> Workload:
        make = _typed_w1_generic if api.startswith("add(") else _typed_w1
        return Workload(lambda: make(n, named), _typed_export)

    def w2_path(self, path: str) -> Workload:
        return Workload(lambda: mjcf_t.from_path(path), _typed_export)

    def w2_text(self, text: str) -> Workload:
        return Workload(lambda: mjcf_t.from_xml_string(text), _typed_export)

    def w3(self, k: int) -> Workload:
        return Workload(lambda: _typed_w3(k), _typed_export)


def _typed_export(model: Any) -> str:
    return str(model.to_xml_string())


def _typed_w1(n: int, named: bool) -> Any:
    root = mjcf_t.RootElement(model="w1")
    worldbody, actuator, sensor = root.worldbody, root.actuator, root.sensor
    for c in range(n // CHAIN):
        parent: Any = worldbody
        for k in range(CHAIN):
            i = c * CHAIN + k
            pos = chain_pos(c) if k == 0 else LINK_POS
            jname = f"j{i}"
            if named:
                body = parent.add_body(name=f"b{i}", pos=pos)
                joint = body.add_joint(name=jname, type="hinge", axis=AXIS)
                body.add_geom(name=f"g{i}", type="capsule", size=SIZE, fromto=FROMTO)
                body.add_site(name=f"s{i}", pos=SITE_POS)
                actuator.add_motor(name=f"m{i}", joint=jname, ctrlrange=CTRLRANGE)
                sensor.add_jointpos(name=f"p{i}", joint=joint)
            else:
                body = parent.add_body(pos=pos)
                joint = body.add_joint(name=jname, type="hinge", axis=AXIS)
                body.add_geom(type="capsule", size=SIZE, fromto=FROMTO)
                body.add_site(pos=SITE_POS)
                actuator.add_motor(joint=jname, ctrlrange=CTRLRANGE)
                sensor.add_jointpos(joint=joint)
            parent = body
    return root


def _typed_w1_generic(n: int, named: bool) -> Any:
    root = mjcf_t.RootElement(model="w1")
    worldbody, actuator, sensor = root.worldbody, root.actuator, root.sensor
    for c in range(n // CHAIN):
        parent: Any = worldbody
        for k in range(CHAIN):
            i = c * CHAIN + k
            pos = chain_pos(c) if k == 0 else LINK_POS
            jname = f"j{i}"
            if named:
                body = parent.add("body", name=f"b{i}", pos=pos)
                joint = body.add("joint", name=jname, type="hinge", axis=AXIS)
                body.add("geom", name=f"g{i}", type="capsule", size=SIZE, fromto=FROMTO)
                body.add("site", name=f"s{i}", pos=SITE_POS)
                actuator.add("motor", name=f"m{i}", joint=jname, ctrlrange=CTRLRANGE)
                sensor.add("jointpos", name=f"p{i}", joint=joint)
            else:
                body = parent.add("body", pos=pos)
                joint = body.add("joint", name=jname, type="hinge", axis=AXIS)
                body.add("geom", type="capsule", size=SIZE, fromto=FROMTO)
                body.add("site", pos=SITE_POS)
                actuator.add("motor", joint=jname, ctrlrange=CTRLRANGE)
                sensor.add("jointpos", joint=joint)
            parent = body
    return root


def _typed_arm(name: str) -> Any:
    arm = mjcf_t.RootElement(model=name)
    cls = arm.default.add_default(class_="arm")
    cls.joint.armature = 0.01
    cls.geom.rgba = RGBA
    parent: Any = arm.worldbody
    joints = []
    for k in range(ARM_LINKS):
        body = parent.add_body(name=f"link{k}", pos=LINK_POS)
        joints.append(body.add_joint(name=f"j{k}", class_="arm", type="hinge", axis=AXIS))
        body.add_geom(class_="arm", type="capsule", size=SIZE, fromto=FROMTO)
        parent = body
    parent.add_site(name="tip")
    for k, joint in enumerate(joints):
        arm.actuator.add_motor(name=f"m{k}", joint=joint, ctrlrange=CTRLRANGE)
    return arm


def _typed_w3(k: int) -> Any:
    world = mjcf_t.RootElement(model="world")
    worldbody = world.worldbody
    for i in range(k):
        site = worldbody.add_site(name=f"mount{i}", pos=mount_pos(i))
        site.attach(_typed_arm(f"arm{i}"))
    return world


# =============================================================================== dm_control


class DmControl(Adapter):
    key = "dm_control"
    title = "dm_control.mjcf"

    def load(self) -> None:
        import warnings

        global mjcf_d
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # it probes for a display when imported
            from dm_control import mjcf as mjcf_d

    def version(self) -> str:
        from importlib.metadata import version

        return version("dm_control")

    def w1_apis(self) -> tuple[str, ...]:
        return ('add("<tag>")',)

    def w1(self, n: int, named: bool, api: str) -> Workload:
        return Workload(lambda: _dm_w1(n, named), _dm_export)

    def w2_path(self, path: str) -> Workload:
        return Workload(lambda: mjcf_d.from_path(path), _dm_export)

    def w2_text(self, text: str) -> Workload:
        return Workload(lambda: mjcf_d.from_xml_string(text), _dm_export)

    def w3(self, k: int) -> Workload:
        return Workload(lambda: _dm_w3(k), _dm_export)


def _dm_export(model: Any) -> str:
    return str(model.to_xml_string())


def _dm_w1(n: int, named: bool) -> Any:
    root = mjcf_d.RootElement(model="w1")
    worldbody, actuator, sensor = root.worldbody, root.actuator, root.sensor
    for c in range(n // CHAIN):
        parent: Any = worldbody
        for k in range(CHAIN):
            i = c * CHAIN + k
            pos = chain_pos(c) if k == 0 else LINK_POS
            if named:
                jname = f"j{i}"
                body = parent.add("body", name=f"b{i}", pos=pos)
                joint = body.add("joint", name=jname, type="hinge", axis=AXIS)
                body.add("geom", name=f"g{i}", type="capsule", size=SIZE, fromto=FROMTO)
                body.add("site", name=f"s{i}", pos=SITE_POS)
                actuator.add("motor", name=f"m{i}", joint=jname, ctrlrange=CTRLRANGE)
                sensor.add("jointpos", name=f"p{i}", joint=joint)
            else:  # unnamed joints, referred to as elements: dm_control names them at export
                body = parent.add("body", pos=pos)
                joint = body.add("joint", type="hinge", axis=AXIS)
                body.add("geom", type="capsule", size=SIZE, fromto=FROMTO)
                body.add("site", pos=SITE_POS)
                actuator.add("motor", joint=joint, ctrlrange=CTRLRANGE)
                sensor.add("jointpos", joint=joint)
            parent = body
    return root


def _dm_arm(name: str) -> Any:
    arm = mjcf_d.RootElement(model=name)
    cls = arm.default.add("default", dclass="arm")
    cls.joint.armature = 0.01
    cls.geom.rgba = RGBA
    parent: Any = arm.worldbody
    joints = []
    for k in range(ARM_LINKS):
        body = parent.add("body", name=f"link{k}", pos=LINK_POS)
        joints.append(body.add("joint", name=f"j{k}", dclass="arm", type="hinge", axis=AXIS))
        body.add("geom", dclass="arm", type="capsule", size=SIZE, fromto=FROMTO)
        parent = body
    parent.add("site", name="tip")
    for k, joint in enumerate(joints):
        arm.actuator.add("motor", name=f"m{k}", joint=joint, ctrlrange=CTRLRANGE)
    return arm


def _dm_w3(k: int) -> Any:
    world = mjcf_d.RootElement(model="world")
    worldbody = world.worldbody
    for i in range(k):
        site = worldbody.add("site", name=f"mount{i}", pos=mount_pos(i))
        site.attach(_dm_arm(f"arm{i}"))
    return world


# =============================================================================== MjSpec


class MjSpecAdapter(Adapter):
    key = "mjspec"
    title = "mujoco.MjSpec"

    def load(self) -> None:
        global mujoco
        import mujoco

    def version(self) -> str:
        return str(mujoco.__version__)

    def w1(self, n: int, named: bool, api: str) -> Workload:
        return Workload(lambda: _spec_w1(n, named), _spec_export)

    def w2_path(self, path: str) -> Workload:
        return Workload(lambda: mujoco.MjSpec.from_file(path), _spec_export)

    def w2_text(self, text: str) -> Workload:
        return Workload(lambda: mujoco.MjSpec.from_string(text), _spec_export)

    def w3(self, k: int) -> Workload:
        return Workload(lambda: _spec_w3(k), _spec_export)


def _spec_export(spec: Any) -> str:
    return str(spec.to_xml())  # compiles the spec itself: no cheaper valid export exists


def _spec_w1(n: int, named: bool) -> Any:
    hinge, capsule = mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtGeom.mjGEOM_CAPSULE
    by_joint, jointpos = mujoco.mjtTrn.mjTRN_JOINT, mujoco.mjtSensor.mjSENS_JOINTPOS
    joint_object = mujoco.mjtObj.mjOBJ_JOINT
    size = [SIZE[0], 0.0, 0.0]
    spec = mujoco.MjSpec()
    spec.modelname = "w1"
    worldbody = spec.worldbody
    for c in range(n // CHAIN):
        parent: Any = worldbody
        for k in range(CHAIN):
            i = c * CHAIN + k
            pos = chain_pos(c) if k == 0 else LINK_POS
            jname = f"j{i}"
            if named:
                body = parent.add_body(name=f"b{i}", pos=pos)
                body.add_joint(name=jname, type=hinge, axis=AXIS)
                body.add_geom(name=f"g{i}", type=capsule, size=size, fromto=FROMTO)
                body.add_site(name=f"s{i}", pos=SITE_POS)
                motor = spec.add_actuator(name=f"m{i}", target=jname, trntype=by_joint)
                spec.add_sensor(name=f"p{i}", type=jointpos, objtype=joint_object,
                                objname=jname)
            else:
                body = parent.add_body(pos=pos)
                body.add_joint(name=jname, type=hinge, axis=AXIS)
                body.add_geom(type=capsule, size=size, fromto=FROMTO)
                body.add_site(pos=SITE_POS)
                motor = spec.add_actuator(target=jname, trntype=by_joint)
                spec.add_sensor(type=jointpos, objtype=joint_object, objname=jname)
            motor.set_to_motor()
            motor.ctrlrange = CTRLRANGE
            parent = body
    return spec


def _spec_arm(name: str) -> Any:
    spec = mujoco.MjSpec()
    spec.modelname = name
    cls = spec.add_default("arm", spec.default)
    cls.joint.armature = 0.01
    cls.geom.rgba = RGBA
    hinge, capsule = mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtGeom.mjGEOM_CAPSULE
    size = [SIZE[0], 0.0, 0.0]
    parent: Any = spec.worldbody
    for k in range(ARM_LINKS):
        body = parent.add_body(name=f"link{k}", pos=LINK_POS)
        body.add_joint(cls, name=f"j{k}", type=hinge, axis=AXIS)
        body.add_geom(cls, type=capsule, size=size, fromto=FROMTO)
        parent = body
    parent.add_site(name="tip")
    for k in range(ARM_LINKS):
        motor = spec.add_actuator(name=f"m{k}", target=f"j{k}", trntype=mujoco.mjtTrn.mjTRN_JOINT)
        motor.set_to_motor()
        motor.ctrlrange = CTRLRANGE
    return spec


def _spec_w3(k: int) -> Any:
    world = mujoco.MjSpec()
    world.modelname = "world"
    worldbody = world.worldbody
    for i in range(k):
        site = worldbody.add_site(name=f"mount{i}", pos=mount_pos(i))
        world.attach(_spec_arm(f"arm{i}"), prefix=f"arm{i}/", site=site)
    return world


# =============================================================================== raw lxml


class RawLxml(Adapter):
    key = "lxml"
    title = "raw lxml (floor)"

    def load(self) -> None:
        global etree
        from lxml import etree

    def version(self) -> str:
        return ".".join(map(str, etree.LXML_VERSION))

    def w1(self, n: int, named: bool, api: str) -> Workload:
        return Workload(lambda: _lxml_w1(n, named), _lxml_export)

    def w2_path(self, path: str) -> Workload:
        return Workload(lambda: _lxml_parse_path(path), _lxml_export)

    def w2_text(self, text: str) -> Workload:
        return Workload(lambda: _lxml_parse_text(text), _lxml_export)

    def w3(self, k: int) -> Workload:
        return Workload(lambda: _lxml_w3(k), _lxml_export)


def _lxml_export(node: Any) -> str:
    return str(etree.tostring(node, pretty_print=True, encoding="unicode"))


def _numbers(values: tuple[float, ...]) -> str:
    return " ".join(map(str, values))


def _lxml_w1(n: int, named: bool) -> Any:
    sub = etree.SubElement
    root = etree.Element("mujoco", {"model": "w1"})
    worldbody = sub(root, "worldbody")
    actuator = sub(root, "actuator")
    sensor = sub(root, "sensor")
    for c in range(n // CHAIN):
        parent = worldbody
        for k in range(CHAIN):
            i = c * CHAIN + k
            pos = _numbers(chain_pos(c) if k == 0 else LINK_POS)
            jname = f"j{i}"
            if named:
                body = sub(parent, "body", {"name": f"b{i}", "pos": pos})
                sub(body, "joint", {"name": jname, "type": "hinge", "axis": _numbers(AXIS)})
                sub(body, "geom", {"name": f"g{i}", "type": "capsule", "size": _numbers(SIZE),
                                   "fromto": _numbers(FROMTO)})
                sub(body, "site", {"name": f"s{i}", "pos": _numbers(SITE_POS)})
                sub(actuator, "motor", {"name": f"m{i}", "joint": jname,
                                        "ctrlrange": _numbers(CTRLRANGE)})
                sub(sensor, "jointpos", {"name": f"p{i}", "joint": jname})
            else:
                body = sub(parent, "body", {"pos": pos})
                sub(body, "joint", {"name": jname, "type": "hinge", "axis": _numbers(AXIS)})
                sub(body, "geom", {"type": "capsule", "size": _numbers(SIZE),
                                   "fromto": _numbers(FROMTO)})
                sub(body, "site", {"pos": _numbers(SITE_POS)})
                sub(actuator, "motor", {"joint": jname, "ctrlrange": _numbers(CTRLRANGE)})
                sub(sensor, "jointpos", {"joint": jname})
            parent = body
    return root


def _lxml_parser() -> Any:
    return etree.XMLParser(resolve_entities=False, no_network=True, remove_comments=True)


def _lxml_parse_text(text: str) -> Any:
    return etree.fromstring(text.encode("utf-8"), _lxml_parser())


def _lxml_parse_path(path: str) -> Any:
    """Parse a file and splice the children of its ``<include>``d files in their place."""
    root = etree.parse(path, _lxml_parser()).getroot()
    folder = os.path.dirname(path)
    for include in list(root.iter("include")):
        parent = include.getparent()
        included = etree.parse(os.path.join(folder, include.get("file")), _lxml_parser())
        at = parent.index(include)
        parent.remove(include)
        for offset, child in enumerate(list(included.getroot())):
            parent.insert(at + offset, child)
    return root


def _lxml_w3(k: int) -> Any:
    sub = etree.SubElement
    root = etree.Element("mujoco", {"model": "world"})
    default = sub(root, "default")
    worldbody = sub(root, "worldbody")
    actuator = sub(root, "actuator")
    for i in range(k):
        scope = f"arm{i}/"
        outer = sub(default, "default", {"class": scope})
        cls = sub(outer, "default", {"class": scope + "arm"})
        sub(cls, "joint", {"armature": str(0.01)})
        sub(cls, "geom", {"rgba": _numbers(RGBA)})
        pos = _numbers(mount_pos(i))
        sub(worldbody, "site", {"name": f"mount{i}", "pos": pos})
        parent = sub(worldbody, "body", {"pos": pos, "childclass": scope})
        for j in range(ARM_LINKS):
            parent = sub(parent, "body", {"name": f"{scope}link{j}", "pos": _numbers(LINK_POS)})
            sub(parent, "joint", {"name": f"{scope}j{j}", "class": scope + "arm",
                                  "type": "hinge", "axis": _numbers(AXIS)})
            sub(parent, "geom", {"class": scope + "arm", "type": "capsule",
                                 "size": _numbers(SIZE), "fromto": _numbers(FROMTO)})
        sub(parent, "site", {"name": f"{scope}tip"})
        for j in range(ARM_LINKS):
            sub(actuator, "motor", {"name": f"{scope}m{j}", "joint": f"{scope}j{j}",
                                    "ctrlrange": _numbers(CTRLRANGE), "class": scope})
    return root


ADAPTERS: dict[str, type[Adapter]] = {
    a.key: a for a in (TypedMjcf, DmControl, MjSpecAdapter, RawLxml)
}

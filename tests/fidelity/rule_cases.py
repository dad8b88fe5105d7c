"""One refused and one accepted model for every rule of the validation tables.

The rules are read from the grammar tables at run time (each row's presence constraints,
``required`` and ``bounds`` attributes: schema/mjcf.json, filled from the grammar file and
schema/facts.toml), so a new row is a new rule here. For each rule :func:`cases` builds MJCF
from the row's context in :data:`ROWS` (where the element sits, and the attributes that make it
legal) and the attribute values in :data:`VALUES`: the model that breaks the rule and the
nearest legal variants (the bundle alone, a value MuJoCo reads as "off", the attributes split
between a class and the class below it). A rule whose row has no context has no case: the test
of every rule says so.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.grammar import AttributeSpec, ElementSpec

# A world with something of every kind a rule's element may name.
WORLD = (
    '<asset><mesh name="me" vertex="0 0 0 1 0 0 0 1 0 0 0 1"/>'
    '<texture name="tx" builtin="flat" width="4" height="4"/></asset>'
    '<worldbody><body name="b"><joint name="j" range="0 1"/><geom name="g" size="0.1"/>'
    '<site name="s"/><site name="s2" pos="0 0 1"/><camera name="c" resolution="10 10"/></body>'
    '<body name="b2" pos="1 0 0"><joint name="j2" type="ball"/><geom name="g2" size="0.1"/>'
    '</body><body name="b3" pos="0 1 0"/></worldbody>'
    '<tendon><fixed name="t" range="0 1"><joint joint="j" coef="1"/></fixed></tendon>'
    '<actuator><motor name="a" joint="j"/></actuator>')
FLEX = ('<deformable><flex name="f" dim="2" body="b b2 b3" vertex="0 0 0 1 0 0 0 1 0" '
        'element="0 1 2"/></deformable>')
# MuJoCo's PID plugin: an instance some actuator uses, and one setting of it
PID = ('<extension><plugin plugin="mujoco.pid">{}</plugin></extension>'
       + WORLD.replace('<actuator>', '<actuator><plugin joint="j" instance="i"/>'))


def world(*parts: str) -> str:
    return WORLD + "".join(parts)


# row -> (where the element goes: "{}" in the model's text, its attributes when legal)
ROWS: dict[str, tuple[str, dict[str, str]]] = {
    "actuator_plugin": ('<extension><plugin plugin="mujoco.pid"><instance name="i"/></plugin>'
                        '</extension>' + world("<actuator>{}</actuator>"),
                        {"joint": "j", "instance": "i"}),
    "sensor_plugin": ('<extension><plugin plugin="mujoco.sensor.touch_grid"><instance name="i">'
                      '<config key="nchannel" value="1"/><config key="size" value="2 2"/>'
                      '<config key="fov" value="45 45"/><config key="gamma" value="0"/>'
                      '</instance></plugin></extension>' + world("<sensor>{}</sensor>"),
                      {"objtype": "site", "objname": "s", "instance": "i"}),
    "plugin": (('<extension><plugin plugin="mujoco.sdf.torus"><instance name="i"><config '
               'key="radius1" value="0.35"/><config key="radius2" value="0.15"/></instance>'
               '</plugin></extension><asset><mesh name="torus">{}</mesh></asset><worldbody>'
               '<geom type="sdf" mesh="torus"/></worldbody>'), {"instance": "i"}),
    "extension_plugin": ("<extension>{}</extension>", {"plugin": "mujoco.pid"}),
    "instance": (PID, {"name": "i"}),
    "config": (PID.format('<instance name="i">{}</instance>'), {"key": "kp", "value": "1"}),
    "attach": (('<worldbody><body name="src"><geom size="0.1"/></body><frame name="fr"/>'
               '<body name="host">{}</body></worldbody>'), {"body": "src", "prefix": "p"}),
    "body": ("<worldbody>{}</worldbody>", {}),
    "frame": ("<worldbody>{}</worldbody>", {}),
    "geom": ("<worldbody>{}</worldbody>", {"size": "0.1"}),
    "site": ("<worldbody>{}</worldbody>", {}),
    "camera": ("<worldbody>{}</worldbody>", {"resolution": "10 10"}),
    "light": ("<worldbody>{}</worldbody>", {}),
    "inertial": ("<worldbody><body>{}</body></worldbody>", {"pos": "0 0 0", "mass": "1"}),
    "replicate": ("<worldbody>{}</worldbody>", {"count": "2"}),
    "flexcomp": ("<worldbody>{}</worldbody>", {"name": "fc", "type": "grid", "count": "2 2 1",
                                                "spacing": "1 1 1", "dim": "2"}),
    "connect": (world("<equality>{}</equality>"), {"body1": "b", "anchor": "0 0 0"}),
    "weld": (world("<equality>{}</equality>"), {"body1": "b"}),
    "equality_joint": (world("<equality>{}</equality>"), {"joint1": "j"}),
    "equality_tendon": (world("<equality>{}</equality>"), {"tendon1": "t"}),
    "equality_flex": (world(FLEX, "<equality>{}</equality>"), {"flex": "f"}),
    "exclude": (world("<contact>{}</contact>"), {"body1": "b", "body2": "b2"}),
    "fixed_joint": (world('<tendon><fixed>{}</fixed></tendon>'), {"joint": "j", "coef": "1"}),
    "spatial_site": (world('<tendon><spatial><site site="s"/>{}</spatial></tendon>'),
                     {"site": "s2"}),
    "spatial_geom": (world('<tendon><spatial><site site="s"/>{}<site site="s2"/></spatial>'
                           '</tendon>'), {"geom": "g2"}),
    "pulley": (world('<tendon><spatial><site site="s"/><site site="s2"/>{}<site site="s"/>'
                     '<site site="s2"/></spatial></tendon>'), {"divisor": "1"}),
    "flex": (world("<deformable>{}</deformable>"),
             {"name": "f2", "dim": "2", "body": "b b2 b3", "vertex": "0 0 0 1 0 0 0 1 0",
              "element": "0 1 2"}),
    "hfield": ("<asset>{}</asset>", {"name": "h", "nrow": "2", "ncol": "2", "size": "1 1 1 1"}),
    "mesh": ("<asset>{}</asset>", {"name": "m2", "vertex": "0 0 0 1 0 0 0 1 0 0 0 1"}),
    "model": ("<asset>{}</asset>", {"name": "child", "file": "child.xml"}),
    "layer": (('<asset><texture name="tx" builtin="flat" width="4" height="4"/>'
              '<material name="m">{}</material></asset>'), {"texture": "tx", "role": "rgb"}),
    "bone": (world('<asset><skin name="sk" vertex="0 0 0 1 0 0 0 1 0" face="0 1 2">{}</skin>'
                   '</asset>'),
             {"body": "b", "bindpos": "0 0 0", "bindquat": "1 0 0 0", "vertid": "0 1 2",
              "vertweight": "1 1 1"}),
    "skin": (world("<asset>{}</asset>"), {"vertex": "0 0 0 1 0 0 0 1 0", "face": "0 1 2"}),
    "numeric": ("<custom>{}</custom>", {"name": "n", "size": "1"}),
    "text": ("<custom>{}</custom>", {"name": "tx", "data": "hello"}),
    "tuple": (world("<custom>{}</custom>"), {"name": "tu"}),
    "element": (world('<custom><tuple name="tu">{}</tuple></custom>'),
                {"objtype": "body", "objname": "b"}),
    "statistic": ("{}", {}),
    "global": ("<visual>{}</visual>", {}),
    "map": ("<visual>{}</visual>", {}),
    "option": ("{}", {}),
    "size": ("{}", {}),
    "adhesion": (world("<actuator>{}</actuator>"), {"body": "b", "ctrlrange": "0 1"}),
    "dcmotor": (world("<actuator>{}</actuator>"),
                {"joint": "j", "motorconst": "1", "resistance": "1"}),
    "user": (world("<sensor>{}</sensor>"), {"dim": "1"}),
    "sensor_contact": (world("<sensor>{}</sensor>"), {"geom1": "g"}),
    "rangefinder": (world("<sensor>{}</sensor>"), {"site": "s"}),
    "camprojection": (world("<sensor>{}</sensor>"), {"site": "s", "camera": "c"}),
    "insidesite": (world("<sensor>{}</sensor>"), {"site": "s", "objtype": "body",
                                                   "objname": "b2"}),
    "tactile": (world("<sensor>{}</sensor>"), {"geom": "g", "mesh": "me"}),
}
for _row in ("general", "motor", "position", "velocity", "intvelocity", "cylinder", "pid"):
    ROWS[_row] = (world("<actuator>{}</actuator>"), {"joint": "j"})
ROWS["muscle"] = (world("<actuator>{}</actuator>"), {"joint": "j", "lengthrange": "0.1 1"})
for _row in ("distance", "normal", "fromto"):
    ROWS[_row] = (world("<sensor>{}</sensor>"), {"geom1": "g", "geom2": "g2"})
ROWS["damper"] = (world("<actuator>{}</actuator>"), {"joint": "j", "ctrlrange": "0 1"})
ROWS["flexstrain"] = (('<worldbody><flexcomp name="fc" type="grid" count="3 3 3" spacing="1 1 1" '
                      'dim="3" dof="trilinear"/></worldbody><equality>{}</equality>'),
                      {"flex": "fc", "cell": "0 0 0"})
for _row, _attribute, _text in (
        *((r, "site", "s") for r in ("accelerometer", "force", "gyro", "magnetometer", "torque",
                                      "touch", "velocimeter")),
        *((r, "actuator", "a") for r in ("actuatorfrc", "actuatorpos", "actuatorvel")),
        *((r, "joint", "j2") for r in ("ballangvel", "ballquat")),
        *((r, "joint", "j") for r in ("jointactuatorfrc", "jointlimitfrc", "jointlimitpos",
                                       "jointlimitvel", "jointpos", "jointvel")),
        *((r, "tendon", "t") for r in ("tendonactuatorfrc", "tendonlimitfrc", "tendonlimitpos",
                                        "tendonlimitvel", "tendonpos", "tendonvel")),
        *((r, "body", "b") for r in ("subtreeangmom", "subtreecom", "subtreelinvel"))):
    ROWS[_row] = (world("<sensor>{}</sensor>"), {_attribute: _text})
for _row in ("frameangacc", "frameangvel", "framelinacc", "framelinvel", "framepos",
             "framequat", "framexaxis", "frameyaxis", "framezaxis"):
    ROWS[_row] = (world("<sensor>{}</sensor>"), {"objtype": "body", "objname": "b"})

# An attribute's value when a case sets it (by name; by "row@name" where the row differs).
VALUES: dict[str, str] = {
    "quat": "1 0 0 0", "axisangle": "0 0 1 0", "xyaxes": "1 0 0 0 1 0", "zaxis": "0 0 1",
    "euler": "0 0 0", "fullinertia": "1 1 1 0 0 0", "fovy": "45", "sensorsize": "1 1",
    "directional": "true", "type": "spot", "memory": "1M", "nstack": "100", "njmax": "10",
    "body": "b", "frame": "fr", "site1": "s", "site2": "s2", "body1": "b", "body2": "b2",
    "anchor": "0 0 0", "relpose": "0 0 0 1 0 0 0", "geom1": "g", "geom2": "g2",
    "subtree1": "b", "subtree2": "b2", "site": "s", "camera": "c", "reftype": "body",
    "refname": "b2", "objtype": "body", "objname": "b", "kv": "1", "dampratio": "1",
    "ctrlrange": "0 1", "actrange": "0 1", "posrange": "0 1", "inheritrange": "1",
    "cranklength": "1", "cranksite": "s", "slidersite": "s2", "refsite": "s2",
    "builtin": "sphere", "params": "1", "file": "m.stl", "vertex": "0 0 0 1 0 0 0 1 0 0 0 1",
    "size": "1", "data": "1", "plugin": "mujoco.pid", "instance": "i",
    "user@objtype": "body", "user@objname": "b", "attach@body": "src",
    "sensor_contact@site": "s", "weld@body1": "b",
}

# The children of an element that MuJoCo needs (a skin's bones, a tuple's elements).
CHILDREN: dict[str, str] = {
    "skin": '<bone body="b" bindpos="0 0 0" bindquat="1 0 0 0" vertid="0 1 2" '
            'vertweight="1 1 1"/>',
    "tuple": '<element objtype="body" objname="b"/>',
}

# Attributes a case leaves out when it sets the key's (another transmission, another way to
# name an object): a slider-crank has no joint.
DISPLACES: dict[str, tuple[str, ...]] = {
    "cranksite": ("joint", "body"), "site": ("joint", "body"), "camera": ("site",),
    "instance": ("plugin",), "plugin": ("instance",), "builtin": ("vertex", "file"),
    **{name: ("body1", "body2", "anchor", "relpose") for name in ("site1", "site2")},
}
# Attributes a case adds when it sets the key's: a slider-crank needs its slider site.
BRINGS: dict[str, dict[str, str]] = {"cranksite": {"slidersite": "s2", "cranklength": "1"},
                                     "builtin": {"params": "1"}}
# Numbers outside a rule's bounds and the nearest inside, where one number repeated is not.
BOUND_VALUES: dict[str, tuple[str, str]] = {"damper@ctrlrange": ("-1 1", "0 1")}


@dataclass(frozen=True)
class Rule:
    """One rule of the tables: ``kind`` is a constraint's kind, ``required`` or ``bounds``."""

    row: str
    kind: str
    bundles: tuple[tuple[str, ...], ...]  # the attribute alone for required and bounds

    @property
    def ident(self) -> str:
        return f"{self.row}:{self.kind}:{'|'.join('+'.join(b) for b in self.bundles)}"


@dataclass(frozen=True)
class Case:
    refused: str  # a model (text) breaking the rule
    accepted: dict[str, str]  # nearest legal variants, by what they show


@functools.cache
def specs() -> dict[str, ElementSpec]:
    return {cls.spec.row: cls.spec for cls in _tree.element_classes().values()}


def rules() -> list[Rule]:
    """Every rule of the tables, on the element rows (a <default> row has its row's)."""
    found: list[Rule] = []
    for row, spec in sorted(specs().items()):
        if spec.row.startswith("default_"):
            continue
        found += [Rule(row, kind, bundles) for kind, bundles in spec.constraints]
        found += [Rule(row, "required", ((a.name,),)) for a in spec.attributes.values()
                  if a.required]
        found += [Rule(row, "bounds", ((a.name,),)) for a in spec.attributes.values()
                  if a.bounds]
    return found


def _value(row: str, name: str) -> str:
    return VALUES.get(f"{row}@{name}", VALUES.get(name, "1"))


def _with(row: str, attrs: Mapping[str, str], names: tuple[str, ...], *,
          displace: bool = True) -> dict[str, str]:
    """``attrs`` and ``names`` set (what they displace left out, unless not ``displace``)."""
    out = dict(attrs)
    for name in names if displace else ():
        for gone in DISPLACES.get(name, ()):
            out.pop(gone, None)
    for name in names:
        out[name] = _value(row, name)
        for brought, value in BRINGS.get(name, {}).items():
            out.setdefault(brought, value)
    return out


def _without(attrs: Mapping[str, str], names: tuple[str, ...]) -> dict[str, str]:
    return {k: v for k, v in attrs.items() if k not in names}


def element_text(tag: str, attrs: Mapping[str, str], inner: str = "") -> str:
    start = "<" + tag + "".join(f' {k}="{v}"' for k, v in attrs.items())
    return f"{start}>{inner}</{tag}>" if inner else f"{start}/>"


def _model(rule: Rule, attrs: Mapping[str, str]) -> str:
    context, _ = ROWS[rule.row]
    element = element_text(specs()[rule.row].tag, attrs, CHILDREN.get(rule.row, ""))
    return f"<mujoco>{context.format(element)}</mujoco>"


def _number_outside(attribute: AttributeSpec) -> tuple[str, str]:
    """A number outside the attribute's bounds, and the nearest inside (each value alike)."""
    op, limit = attribute.bounds[0]
    step = 1.0
    outside, inside = {">": (limit, limit + step), ">=": (limit - step, limit),
                       "<": (limit, limit - step), "<=": (limit + step, limit)}[op]
    if len(attribute.bounds) > 1:  # a range: the first bound's side is outside alone
        inside = limit
    count = max(attribute.lo, 1) if attribute.is_array else 1

    def spell(x: float) -> str:
        return str(int(x)) if attribute.kind == "int" else f"{x:g}"
    return " ".join([spell(outside)] * count), " ".join([spell(inside)] * count)


def _default_text(tag: str, parent: Mapping[str, str], child: Mapping[str, str]) -> str:
    return (f"<mujoco><default>{element_text(tag, parent)}<default class=\"c\">"
            f"{element_text(tag, child)}</default></default></mujoco>")


def cases(rule: Rule) -> Case | None:
    """The models of ``rule``, or None when its row has no context in :data:`ROWS`."""
    if rule.row not in ROWS:
        return None
    _, base = ROWS[rule.row]
    spec = specs()[rule.row]
    tag = spec.tag
    bundles = rule.bundles
    accepted: dict[str, str] = {}
    if rule.kind == "required":
        (name,), = bundles
        refused = _model(rule, _without(base, (name,)))
        accepted["set"] = _model(rule, base)
    elif rule.kind == "bounds":
        (name,), = bundles
        outside, inside = BOUND_VALUES.get(f"{rule.row}@{name}",
                                           _number_outside(spec.by_name[name]))
        refused = _model(rule, {**base, name: outside})
        accepted["at the bound"] = _model(rule, {**base, name: inside})
    elif rule.kind == "exclusive":
        first, second = bundles[0], bundles[1]
        refused = _model(rule, _with(rule.row, _with(rule.row, base, first), second,
                                     displace=False))
        accepted["one bundle"] = _model(rule, _with(rule.row, _without(base, second), first))
        default = specs().get(f"default_{rule.row}")
        if default is not None and all(n in default.by_name for n in first + second):
            # MuJoCo checks what an element (or class) sets itself, not what it inherits
            accepted["split between classes"] = _default_text(
                tag, {n: _value(rule.row, n) for n in first},
                {n: _value(rule.row, n) for n in second})
        for name in first + second:
            attribute = spec.by_name[name]
            if attribute.off:
                off = " ".join(["0"] * (attribute.lo if attribute.is_array else 1))
                both = _with(rule.row, _with(rule.row, base, first), second, displace=False)
                accepted[f"{name} off"] = _model(rule, {**both, name: off})
    elif rule.kind == "together":
        names = tuple(n for b in bundles for n in b)
        refused = _model(rule, _with(rule.row, base, bundles[0]))
        accepted["all"] = _model(rule, _with(rule.row, base, names))
    elif rule.kind == "requires":
        first, *needed = bundles
        missing = tuple(n for b in needed for n in b)
        refused = _model(rule, _without(_with(rule.row, base, first), missing))
        accepted["with what it requires"] = _model(
            rule, _with(rule.row, base, tuple(n for b in needed for n in b) + first))
    else:  # oneof
        every = tuple(n for b in bundles for n in b)
        refused = _model(rule, _without(base, every))
        # the last bundle: a plugin= alone needs its configuration (an instance= has it)
        accepted["one bundle"] = _model(rule, _with(rule.row, _without(base, every),
                                                    bundles[-1]))
    return Case(refused, accepted)

"""Random MJCF models built only through the typed API, with grammar-valid values.

Values come from the generated ``_SPEC`` tables: keywords (in any letter case), flags,
array lengths within the grammar's bounds, finite floats in sane ranges, small ints; names
are unique. The builder mostly keeps the grammar's exclusive constraints and MuJoCo's
structural rules, and now and then breaks one on purpose (the validator must say so).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import TypeVar

from hypothesis import strategies as st

import typed_mjcf as mjcf
from typed_mjcf import Element
from typed_mjcf._core.grammar import AttributeSpec, ElementSpec
from typed_mjcf._core.tree import element_classes

T = TypeVar("T")

# Attribute kinds drawn at random; names, references, files and free text are set by the
# builder itself (free text has meanings the grammar does not state, e.g. size@memory).
DRAWN_KINDS = frozenset({"bool", "int", "real", "keyword", "flags", "chars"})
MAX_EXTRA_LENGTH = 4  # unbounded arrays get up to lo + 4 values

SPECIAL_DOUBLES = [0.1, 1 / 3, -0.0, 1e-300, 2.5e-8, 123456.789, -7.0]
SPECIAL_FLOATS = [0.1, 1 / 3, -0.0, 0.25, 1e-7]


def _case(word: str) -> st.SearchStrategy[str]:
    return st.sampled_from([word, word.upper(), word.title(), word.lower()])


def number(dtype: str | None) -> st.SearchStrategy[float]:
    if dtype == "float":
        return st.one_of(st.floats(-100, 100, width=32), st.sampled_from(SPECIAL_FLOATS))
    return st.one_of(st.floats(-100, 100, allow_nan=False, allow_infinity=False),
                     st.sampled_from(SPECIAL_DOUBLES))


# Values MuJoCo's parser refuses although the typed schema allows them (the schema carries no
# numeric ranges yet; see test_regressions.py, which checks the library refuses them too). The
# builder draws inside these ranges, so that the property tests the validator, not the gaps.
NON_NEGATIVE = frozenset({"kv", "dampratio", "timeconst", "slewmax", "tausmooth", "gain",
                          "inductance", "actuatorgroupdisable"})
POSITIVE = frozenset({"extent", "realtime", "znear", "resistance", "motorconst"})
NON_NEGATIVE_IN: dict[str, frozenset[str]] = {
    "ctrlrange": frozenset({"adhesion", "damper"}), "posrange": frozenset()}
NOT_DRAWN = frozenset({"thermal",  # dcmotor: needs a consistent set of values
                       "gridlayout", "gridsize",  # texture: lengths must match
                       "cranklength"})  # actuators: only with cranksite
NOT_DRAWN_IN = {"builtin": frozenset({"mesh"})}  # a builtin mesh requires params
# The actuator rows of a default class share one actuator, inherited by nested classes: the
# parser's exclusions (PARSER_EXCLUSIVE) then apply across rows and levels.
NOT_DRAWN_IN_DEFAULTS = frozenset({"inheritrange", "dampratio", "gainprm", "biasprm", "dynprm"})
SPECIAL_VALUES: dict[tuple[str, str], st.SearchStrategy[object]] = {
    ("mesh", "maxhullvert"): st.sampled_from([-1, 4, 5, 100]),
    ("skin", "group"): st.integers(0, 5),
    ("sensor_contact", "num"): st.integers(1, 5),
    # arity 1..3 in the schema, but "attribute 'scale' must have 1 or 3 values"
    ("frame", "scale"): st.sampled_from([1, 3]).flatmap(
        lambda n: st.lists(st.floats(0.25, 4), min_size=n, max_size=n).map(tuple)),
}
# Attributes the parser requires though the schema does not: a dcmotor (also a default
# class's) needs a positive motor constant and resistance, after inheritance.
PARSER_REQUIRED: dict[str, dict[str, object]] = {
    "dcmotor": {"motorconst": (1.0,), "resistance": 1.0}}
# Attributes the parser refuses together though the schema has no such constraint.
PARSER_EXCLUSIVE: dict[str, list[tuple[tuple[str, ...], ...]]] = {
    "position": [(("kv",), ("dampratio",)), (("ctrlrange",), ("inheritrange",))],
    "intvelocity": [(("kv",), ("dampratio",)), (("actrange",), ("inheritrange",))],
    "orientation": [(("kv",), ("dampratio",))],
    "pid": [(("kv",), ("dampratio",)), (("ctrlrange", "posrange"), ("inheritrange",))],
}
# Keywords of the grammar that MuJoCo 4.0.0's parser refuses.
REFUSED_KEYWORDS = {("compiler", "coordinate"): frozenset({"global"})}


def is_drawn(attribute: AttributeSpec, row: str) -> bool:
    primary = row.removeprefix("default_")
    return (attribute.kind in DRAWN_KINDS and attribute.name not in NOT_DRAWN
            and primary not in NOT_DRAWN_IN.get(attribute.name, ())
            and not (row.startswith("default_") and attribute.name in NOT_DRAWN_IN_DEFAULTS))


def value_of(attribute: AttributeSpec, row: str = "") -> st.SearchStrategy[object]:
    """A grammar-valid value for an attribute of a drawn kind."""
    kind = attribute.kind
    primary = row.removeprefix("default_")
    special = SPECIAL_VALUES.get((primary, attribute.name))
    if special is not None:
        return special
    lowest: float | None = None
    if attribute.name in POSITIVE:
        lowest = 0.25
    elif (attribute.name in NON_NEGATIVE or primary in NON_NEGATIVE_IN.get(attribute.name, ())
          or (row.startswith("default_") and attribute.name in NON_NEGATIVE_IN)):
        # the actuator rows of a default class share one actuator: <general ctrlrange> in a
        # class also sets the class's <adhesion ctrlrange>
        lowest = 0.0
    if lowest is not None and kind in ("real", "int"):
        item: st.SearchStrategy[object] = (
            st.integers(int(lowest + 0.75), 5) if kind == "int"
            else st.floats(lowest, 100, width=32 if attribute.dtype == "float" else 64))
        if not attribute.is_array:
            return item
        return st.lists(item, min_size=max(attribute.lo, 1),
                        max_size=min(attribute.hi or attribute.lo + 4, attribute.lo + 4)
                        ).map(tuple)
    if attribute.name == "quat":  # "zero quaternion is not allowed"
        return st.tuples(*[number(attribute.dtype)] * 3).map(lambda v: (1.0, *v))
    if kind == "keyword":
        refused = REFUSED_KEYWORDS.get((row, attribute.name), frozenset())
        keywords = [k for k in attribute.keywords if k not in refused]
        return st.sampled_from(keywords).flatmap(_case)
    if kind == "bool":
        return st.one_of(st.booleans(), st.sampled_from(["true", "false", "TRUE", "False"]))
    if kind == "flags":
        flags = st.lists(st.sampled_from(attribute.keywords), min_size=1, max_size=3,
                         unique=True).map(lambda words: " ".join(words))
        if attribute.alone:  # or one keyword alone (input="none"), in any case
            return st.one_of(flags, st.sampled_from(attribute.alone).flatmap(_case))
        return flags
    if kind == "chars":
        if attribute.pattern is not None:
            return st.from_regex(attribute.pattern, fullmatch=True)
        hi = attribute.hi if attribute.hi is not None else attribute.lo + MAX_EXTRA_LENGTH
        return st.text(alphabet="abcxyz", min_size=max(attribute.lo, 1), max_size=hi)
    item = st.integers(0, 5) if kind == "int" else number(attribute.dtype)
    if not attribute.is_array:
        return item
    lo = attribute.lo
    hi = attribute.hi if attribute.hi is not None else lo + MAX_EXTRA_LENGTH
    hi = min(hi, lo + MAX_EXTRA_LENGTH)
    return st.lists(item, min_size=lo, max_size=hi).map(tuple)


def _rows_by_name() -> dict[str, ElementSpec]:
    return {cls.spec.row: cls.spec for cls in element_classes().values()}


ROWS = _rows_by_name()


def exclusive_groups(spec: ElementSpec) -> list[tuple[tuple[str, ...], ...]]:
    """The exclusive bundles of a row, and of the row a <default> row projects."""
    groups = [bundles for kind, bundles in spec.constraints if kind == "exclusive"]
    primary = ROWS.get(spec.row.removeprefix("default_"))
    if primary is not None and primary is not spec:
        groups += [bundles for kind, bundles in primary.constraints if kind == "exclusive"
                   and all(n in spec.by_name for b in bundles for n in b)]
    return groups


class Builder:
    """Draws a model step by step from a hypothesis ``data`` object."""

    def __init__(self, data: st.DataObject, *, strict: bool) -> None:
        self.data = data
        self.strict = strict  # keep the rules; else break some on purpose
        self.count = 0
        self.model = mjcf.RootElement(model="random")
        self.classes: list[str] = []
        self.named: dict[str, list[Element]] = {}
        # MuJoCo 4.0.0 copies an element that refers into a <replicate> once per replicate,
        # and with several replicates the copies' names can collide ("repeated name 'p0'",
        # e.g. a pair of geoms in two sibling replicates, one holding a nested replicate).
        # validate() cannot tell those cases from the many that work (an upstream bug): the
        # builder leaves such elements unnamed when the model has two or more replicates.
        self.replicates = 0
        self.replicated: set[int] = set()  # ids of elements inside a replicate
        self.inside_replicate = False

    # ------------------------------------------------------------------ drawing

    def draw(self, strategy: st.SearchStrategy[T], label: str | None = None) -> T:
        return self.data.draw(strategy, label=label)

    def chance(self, percent: int) -> bool:
        return self.draw(st.integers(0, 99)) < percent

    def name(self, prefix: str) -> str:
        self.count += 1
        return f"{prefix}{self.count}"

    def attributes(self, spec: ElementSpec, *, skip: Sequence[str] = (),
                   most: int = 4) -> dict[str, object]:
        """Random attributes of drawn kinds, by XML name."""
        candidates = [a for a in spec.attributes.values()
                      if is_drawn(a, spec.row) and a.name not in skip]
        if not candidates:
            return {}
        chosen = self.draw(st.lists(st.sampled_from(candidates), unique_by=lambda a: a.name,
                                    max_size=min(most, len(candidates))))
        values = {a.name: self.draw(value_of(a, spec.row), label=f"{spec.tag}@{a.name}")
                  for a in chosen}
        for name, value in PARSER_REQUIRED.get(spec.row.removeprefix("default_"), {}).items():
            values.setdefault(name, value)
        groups = PARSER_EXCLUSIVE.get(spec.row.removeprefix("default_"), [])
        if self.strict:
            groups = groups + exclusive_groups(spec)
        for bundles in groups:
            touched = [b for b in bundles if any(n in values for n in b)]
            for bundle in touched[1:]:
                for n in bundle:
                    values.pop(n, None)
        return values

    def add(self, parent: Element, tag: str, namespace: str | None = None,
            fixed: Mapping[str, object] | None = None, *, skip: Sequence[str] = (),
            most: int = 4, unnamed: bool = False) -> Element:
        """Add a child with random attributes, the ``fixed`` ones, maybe a name and class."""
        child_spec = parent.spec.children[tag]
        spec = element_classes()[child_spec.class_name].spec
        fixed = fixed or {}
        values = self.attributes(spec, skip=[*skip, *fixed], most=most)
        if (namespace is not None and spec.id_attribute is not None and self.chance(70)
                and not unnamed and not self.refers_into_replicates(fixed.values())):
            values[spec.id_attribute.name] = self.name(tag)
        if "class" in spec.by_name and "class" not in fixed and self.classes and self.chance(30):
            values["class"] = self.draw(st.sampled_from(self.classes))
        values.update(fixed)
        element = parent.add(tag, **{spec.by_name[k].py_name: v for k, v in values.items()})
        if self.inside_replicate:
            self.replicated.add(id(element))
        id_attribute = spec.id_attribute
        if (namespace is not None and id_attribute is not None
                and element.get_attributes().get(id_attribute.py_name) is not None):
            self.named.setdefault(namespace, []).append(element)
        return element

    def refers_into_replicates(self, values: Iterable[object]) -> bool:
        if self.replicates < 2:
            return False
        for value in values:
            if isinstance(value, str):
                value = next((e for es in self.named.values() for e in es
                              if e.get_attributes().get("name") == value), None)
            if isinstance(value, Element) and id(value) in self.replicated:
                return True
        return False

    def target(self, namespace: str) -> object | None:
        """A reference to a named element of ``namespace``: the element or its name."""
        candidates = self.named.get(namespace, [])
        if not candidates:
            return None
        element = self.draw(st.sampled_from(candidates))
        if self.chance(50):
            return element
        id_attribute = element.spec.id_attribute
        assert id_attribute is not None
        return element.get_attributes()[id_attribute.py_name]

    # ------------------------------------------------------------------ sections

    def build(self) -> mjcf.RootElement:
        model = self.model
        self.globals()
        self.defaults()
        self.assets()
        self.tree(model.worldbody, "world", 0)
        self.tendons()
        self.actuators()
        self.sensors()
        self.equalities()
        self.contacts()
        if self.chance(20):
            self.add(model.keyframe, "key", "key")
        if not self.strict and self.chance(50):
            # a reference that names nothing
            model.actuator.add_motor(joint="no-such-joint")
        return model

    def globals(self) -> None:
        """Attributes of the once-only sections (compiler, option, visual/..., ...)."""
        for path in (("compiler",), ("option",), ("statistic",), ("option", "flag"),
                     ("visual", "global"), ("visual", "quality"), ("visual", "headlight")):
            if not self.chance(30):
                continue
            spec = self.model.spec
            for tag in path:
                spec = element_classes()[spec.children[tag].class_name].spec
            values = self.attributes(spec)
            if not values:
                # an empty section inside another is written as an empty tag that does not
                # survive a round trip (test_regressions.py); don't create one
                continue
            section: Element = self.model
            for tag in path:
                existing = section.get_children(tag)
                section = existing[0] if existing else section.add(tag)
            section.set_attributes(**{spec.by_name[k].py_name: v for k, v in values.items()})

    def defaults(self) -> None:
        levels: list[Element] = [self.model.default]
        for _ in range(self.draw(st.integers(0, 3), label="classes")):
            parent = self.draw(st.sampled_from(levels))
            name = self.name("class")
            levels.append(parent.add("default", class_=name))
            self.classes.append(name)
        tags = [t for t in self.model.default.spec.children if t != "default"]
        for level in levels:
            for tag in self.draw(st.lists(st.sampled_from(tags), unique=True, max_size=3)):
                element = self.add(level, tag)
                if not element.get_attributes():
                    element.remove()  # see globals(): an empty section is a known bug
        if not self.strict and self.chance(30):
            self.model.worldbody.add_geom(class_="no-such-class", size=(0.1,))

    def assets(self) -> None:
        asset = self.model.asset
        for _ in range(self.draw(st.integers(0, 1))):
            builtin = self.draw(st.sampled_from(["checker", "flat", "gradient"]))
            self.add(asset, "texture", "texture",
                     {"builtin": builtin, "name": self.name("texture")})
        for _ in range(self.draw(st.integers(0, 2))):
            texture = self.target("texture")
            fixed: dict[str, object] = {"name": self.name("material")}
            if texture is not None and self.chance(50):
                fixed["texture"] = texture
            self.add(asset, "material", "material", fixed)

    def tree(self, container: Element, owner: str, depth: int) -> None:
        """Fill a worldbody, body, frame or replicate; ``owner`` is the enclosing world,
        body or replicate (frames are transparent)."""
        options = ["geom", "site", "geom", "camera", "light"]
        if depth < 3:
            options += ["body", "body", "frame"]
        if depth < 2:
            options.append("replicate")
        if owner == "body" or not self.strict:  # else MuJoCo refuses (and validate says so)
            options += ["joint", "joint", "inertial"]
        if container.tag == "body":
            options.append("freejoint")
        options = [tag for tag in options if tag in container.spec.children]
        for _ in range(self.draw(st.integers(0, 4 if depth == 0 else 3))):
            tag = self.draw(st.sampled_from(options), label=f"child of {container.tag}")
            if tag == "body":
                body = self.add(container, "body", "body", skip=("childclass",))
                if self.classes and self.chance(20):
                    body.set_attributes(childclass=self.draw(st.sampled_from(self.classes)))
                self.tree(body, "body", depth + 1)
            elif tag == "frame":
                self.tree(self.add(container, "frame", "frame"), owner, depth + 1)
            elif tag == "replicate":
                replicate = self.add(container, "replicate", None,
                                     {"count": self.draw(st.integers(1, 3))})
                self.replicates += 1
                inside, self.inside_replicate = self.inside_replicate, True
                self.tree(replicate, "replicate", depth + 1)
                self.inside_replicate = inside
            elif tag == "geom":
                material = self.target("material") if self.chance(20) else None
                self.add(container, "geom", "geom",
                         None if material is None else {"material": material})
            elif tag == "camera":
                target = self.target("body") if self.chance(20) else None
                self.add(container, "camera", "camera",
                         None if target is None else {"target": target})
            elif tag == "inertial":
                if not container.get_children("inertial"):
                    mass = self.draw(st.floats(0.01, 10))
                    self.add(container, "inertial", None, {"pos": (0, 0, 0), "mass": mass})
            elif tag in ("joint", "freejoint"):
                if tag == "freejoint" and (container.get_children("joint")
                                           or container.get_children("freejoint")):
                    continue
                self.add(container, tag, "joint")
            else:
                self.add(container, tag, tag)

    def tendons(self) -> None:
        tendon = self.model.tendon
        joints = [j for j in self.named.get("joint", []) if j.tag == "joint"]
        if joints and self.chance(40):
            members = self.draw(st.lists(st.sampled_from(joints), min_size=1, max_size=2,
                                         unique_by=id))
            fixed = self.add(tendon, "fixed", "tendon", unnamed=self.refers_into_replicates(members))
            for joint in members:
                fixed.add("joint", joint=joint, coef=self.draw(number("double")))
        sites = self.named.get("site", [])
        if len(sites) >= 2 and self.chance(40):
            members = self.draw(st.lists(st.sampled_from(sites), min_size=2, max_size=3,
                                         unique_by=id))
            spatial = self.add(tendon, "spatial", "tendon",
                               unnamed=self.refers_into_replicates(members))
            for site in members:
                spatial.add("site", site=site)

    def actuators(self) -> None:
        actuator = self.model.actuator
        tags = [t for t in actuator.spec.children if t != "plugin"]
        for _ in range(self.draw(st.integers(0, 3), label="actuators")):
            tag = self.draw(st.sampled_from(tags))
            transmissions = [("joint", "joint"), ("tendon", "tendon"), ("site", "site")]
            if tag == "adhesion":
                transmissions = [("body", "body")]
            attribute, namespace = self.draw(st.sampled_from(transmissions))
            target = self.target(namespace)
            spec = element_classes()[actuator.spec.children[tag].class_name].spec
            fixed = None if target is None or attribute not in spec.by_name else {
                attribute: target}
            self.add(actuator, tag, "actuator", fixed)

    def sensors(self) -> None:
        sensor = self.model.sensor
        makers: list[Callable[[], object]] = []

        def by_reference(tag: str, attribute: str, namespace: str) -> Callable[[], None]:
            def make() -> None:
                target = self.target(namespace)
                if target is not None:
                    self.add(sensor, tag, "sensor", {attribute: target})
            return make

        for tag, attribute, namespace in [
            ("jointpos", "joint", "joint"), ("jointvel", "joint", "joint"),
            ("accelerometer", "site", "site"), ("touch", "site", "site"),
            ("gyro", "site", "site"), ("subtreecom", "body", "body"),
            ("actuatorfrc", "actuator", "actuator"), ("tendonpos", "tendon", "tendon"),
        ]:
            makers.append(by_reference(tag, attribute, namespace))

        def frame_sensor() -> None:
            tag = self.draw(st.sampled_from(["framepos", "framequat", "framexaxis",
                                             "framelinvel"]))
            objtype = self.draw(st.sampled_from(["body", "xbody", "geom", "site"]))
            namespace = "body" if objtype == "xbody" else objtype
            candidates = self.named.get(namespace, [])
            if not candidates:
                return
            element = self.draw(st.sampled_from(candidates))
            name = element.get_attributes()["name"]
            self.add(sensor, tag, "sensor", {"objtype": objtype, "objname": name})

        makers += [frame_sensor, lambda: self.add(sensor, "clock", "sensor")]
        for _ in range(self.draw(st.integers(0, 3), label="sensors")):
            self.draw(st.sampled_from(makers))()

    def equalities(self) -> None:
        equality = self.model.equality
        bodies = self.named.get("body", [])
        if bodies and self.chance(30):
            body1 = self.target("body")
            if self.chance(50):
                self.add(equality, "connect", "equality",
                         {"body1": body1, "anchor": (0.0, 0.0, 0.1)})
            else:
                self.add(equality, "weld", "equality", {"body1": body1})
        joints = [j for j in self.named.get("joint", []) if j.tag == "joint"]
        if joints and self.chance(30):
            self.add(equality, "joint", "equality", {"joint1": self.draw(st.sampled_from(joints))})

    def contacts(self) -> None:
        contact = self.model.contact
        geoms = self.named.get("geom", [])
        if len(geoms) >= 2 and self.chance(30):
            g1, g2 = self.draw(st.lists(st.sampled_from(geoms), min_size=2, max_size=2,
                                        unique_by=id))
            self.add(contact, "pair", "pair", {"geom1": g1, "geom2": g2})
        bodies = self.named.get("body", [])
        if len(bodies) >= 2 and self.chance(30):
            b1, b2 = self.draw(st.lists(st.sampled_from(bodies), min_size=2, max_size=2,
                                        unique_by=id))
            self.add(contact, "exclude", "exclude", {"body1": b1, "body2": b2})

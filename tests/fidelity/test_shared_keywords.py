"""Keyword lists shared between tags, probed keyword by keyword against the installed MuJoCo.

MuJoCo's grammar gives several tags one keyword list (``<site type>`` has the geom's), but
the compiler may take only part of it on one tag (a site is never a plane). For every
attribute whose keyword list is shared between tags (or is a part of another tag's list), a
tiny model sets each keyword of the list in turn; MuJoCo loads it or not, and typed-mjcf
must accept exactly the keywords MuJoCo loads: by assignment, and when parsing.

A model is compiled when it compiles without the probed attribute (so the compiler's rules
count too, as for the site); otherwise only MuJoCo's reader judges it (``MjSpec``), which
is where keywords are read. The tiny model puts the element where the grammar allows it,
in a world that has one element named ``x`` of every kind a reference may name, and sets the
element's first reference (and the reference a probed type attribute selects) to ``x``.
"""

from __future__ import annotations

import collections
import functools
from dataclasses import dataclass
from typing import cast

import mujoco
import pytest

import typed_mjcf as mjcf
from codegen import ir, probe
from typed_mjcf._core import tree as _tree
from typed_mjcf._core.grammar import AttributeSpec, ElementSpec
from typed_mjcf.errors import MjcfError

# One named element of each kind a probed element may refer to; ``{body}`` is where the
# probed element goes when it belongs in a body, ``{section}`` when it is a model section's.
WORLD = """<mujoco>
  <asset>
    <mesh name="x" vertex="0 0 0 1 0 0 0 1 0 0 0 1"/>
    <hfield name="x" nrow="2" ncol="2" size="1 1 1 0.1"/>
    <texture name="x" type="2d" builtin="checker" width="8" height="8"/>
  </asset>
  <worldbody>
    <body name="x">
      <joint name="x" type="hinge"/>
      <geom name="x" size="0.1"/>
      <site name="x"/>
      <camera name="x"/>
    </body>
    <body name="probe" pos="0 0 1">
      <geom size="0.1"/>
      {body}
    </body>
  </worldbody>
  <tendon><fixed name="x"><joint joint="x" coef="1"/></fixed></tendon>
  <actuator><motor name="x" joint="x"/></actuator>
  {section}
</mujoco>"""

# Probed keywords that need another attribute to compile at all (the mesh a mesh site
# shows, the height field a height-field geom is).
NEEDS: dict[tuple[str, str], dict[str, str]] = {
    ("site", "mesh"): {"mesh": "x"},
    ("geom", "mesh"): {"mesh": "x"},
    ("geom", "hfield"): {"hfield": "x"},
    ("geom", "plane"): {"size": "1 1 1"},
}

# Keywords the compiler refuses in the probe model for a reason other than the tag: what
# else the element (or the model) says. MuJoCo's message, checked every run, shows it.
CONTEXT: dict[tuple[str, str], str] = {
    # a <general>'s inputs depend on its gaintype, not on its tag
    ("general@input", "ff"): "fixed and affine gains take one input",
    ("general@input", "voltage"): "fixed and affine gains take one input",
    ("general@dyntype", "dcmotor"): "actearly cannot be false for DC motor",
    ("general@dyntype", "pid"): "dyntype 'pid' requires gaintype 'pid'",
    # interpolated degrees of freedom need nodes the probe's flex does not have
    ("flex@dof", "trilinear"): "number of nodes (0) does not match cellcount",
    ("flex@dof", "quadratic"): "number of nodes (0) does not match cellcount",
    ("flexcomp@dof", "trilinear"): "flex grid rotation R0 is not orthonormal",
    ("flexcomp@dof", "quadratic"): "flex grid rotation R0 is not orthonormal",
    # the probe body has no mass of its own but its geom's
    ("compiler@inertiafromgeom", "false"): "mass and inertia of moving bodies",
}

# Values an element needs before MuJoCo reads it at all, beyond what the grammar requires.
EXTRA: dict[str, dict[str, str]] = {
    "dcmotor": {"motorconst": "1", "resistance": "1"},
    "camprojection": {"camera": "x"},
    "distance": {"geom2": "x"}, "fromto": {"geom2": "x"}, "normal": {"geom2": "x"},
    "tactile": {"mesh": "x"}, "insidesite": {"site": "x"},
    "flex": {"name": "f", "body": "x x x", "vertex": "0 0 0 1 0 0 0 1 0", "element": "0 1 2"},
    "flexcomp": {"name": "f", "type": "grid", "count": "2 2 1", "spacing": "0.1 0.1 0.1",
                 "dim": "2"},
}

_NAMESPACES = ("joint", "body", "site", "tendon", "actuator", "geom", "camera")


@dataclass(frozen=True)
class Probe:
    row: str  # the schema row's declaration name
    attribute: str
    candidates: tuple[str, ...]  # the keywords of every list this one shares or is part of

    @property
    def id(self) -> str:
        return f"{self.row}@{self.attribute}"


@functools.cache
def _schema() -> ir.Schema:
    return ir.load()


def shared_attributes() -> list[Probe]:
    """Every keyword attribute (outside default classes) whose keyword list another tag
    shares, or which is a part of another tag's list."""
    schema = _schema()
    uses: dict[str, list[tuple[str, str, str]]] = collections.defaultdict(list)
    for name, row in schema.elements.items():
        if row.tag == "default" or name.startswith("default_"):
            continue
        for attribute in row.attributes:
            if attribute.kind in ("keyword", "flags") and attribute.enum:
                uses[attribute.enum].append((name, row.tag, attribute.name))
    keywords = {enum: set(schema.enums[enum].keywords) for enum in uses}
    probes: list[Probe] = []
    for enum, rows in sorted(uses.items()):
        # the lists this one is part of, on other tags
        wider = [other for other in uses if keywords[enum] < keywords[other]
                 and schema.enums[other].ctype == schema.enums[enum].ctype
                 and {t for _, t, _ in uses[other]} - {t for _, t, _ in rows}]
        narrower = [other for other in uses if keywords[other] < keywords[enum]
                    and schema.enums[other].ctype == schema.enums[enum].ctype
                    and {t for _, t, _ in uses[other]} - {t for _, t, _ in rows}]
        if len({tag for _, tag, _ in rows}) < 2 and not wider and not narrower:
            continue
        candidates = set(keywords[enum]).union(*(keywords[other] for other in wider))
        ordered = tuple(k for k in schema.enums[(wider or [enum])[0]].keywords
                        if k in candidates)
        ordered += tuple(sorted(candidates - set(ordered)))
        probes += [Probe(row, attribute, ordered) for row, _, attribute in rows]
    return probes


def _spec(row: str) -> ElementSpec:
    for cls in _tree.element_classes().values():
        if cls.spec.row == row:
            return cls.spec
    raise AssertionError(f"no generated class for the row {row}")


def _references(spec: ElementSpec, probed: AttributeSpec) -> dict[str, str]:
    """The references that make the element mean something: the object a type attribute
    selects (``objtype="body" objname="x"``; ``x`` in the probed type's namespace), else
    the element's first reference to a namespace of :data:`WORLD`."""
    found: dict[str, str] = {}
    typed = [a for a in spec.attributes.values() if a.namespace_from is not None]
    for i, attribute in enumerate(typed):
        type_attribute = spec.by_name[cast(tuple[str, object], attribute.namespace_from)[0]]
        if type_attribute is probed:
            found[attribute.name] = "x"
        elif i == 0:
            found[type_attribute.name] = "body"
            found[attribute.name] = "x"
    if not typed:
        first = next((a for a in spec.attributes.values() if a.is_reference
                      and isinstance(a.namespace, str) and a.namespace in _NAMESPACES), None)
        if first is not None:
            found[first.name] = "x"
    return found


def _path(row: str) -> tuple[str, ...]:
    """The tags from the root to ``row`` (outside default classes), shortest first."""
    schema = _schema()
    path = probe.path_to(schema, row)
    assert path is not None, f"no path from the root to {row}"
    return tuple(schema.elements[n].tag for n in path)


def _required(row: str) -> dict[str, str]:
    """Values for the attributes the grammar requires that are not references."""
    schema = _schema()
    found: dict[str, str] = {}
    for attribute in schema.elements[row].attributes:
        if attribute.required and attribute.kind not in ("ref", "file"):
            found[attribute.name] = attribute.default or " ".join(
                ["1"] * (attribute.arity[0] if attribute.arity else 1))
    return found


def _extra(tag: str) -> str:
    return "".join(f' {k}="{v}"' for k, v in EXTRA.get(tag, {}).items())


def model_text(probe: Probe, keyword: str | None) -> str:
    """The tiny model: ``probe``'s element where the grammar puts it, ``keyword`` set (or
    the attribute left out)."""
    spec = _spec(probe.row)
    attributes = {**_required(probe.row), **EXTRA.get(spec.tag, {}),
                  **_references(spec, spec.by_name[probe.attribute])}
    probed = spec.by_name[probe.attribute]
    if keyword is None and any(a.namespace_from is not None and a.namespace_from[0] == probed.name
                               for a in spec.attributes.values()):
        keyword = probed.keywords[0]  # a type whose object is named: the first type
    if keyword is not None:
        attributes[probe.attribute] = keyword
        attributes.update(NEEDS.get((spec.tag, keyword), {}))
        if probe.attribute.endswith("limited") and keyword == "true":  # a limit needs a range
            attributes[probe.attribute.removesuffix("limited") + "range"] = "0 1"
            if probe.attribute == "actlimited" and "dyntype" in spec.by_name:  # an activation
                attributes["dyntype"] = "integrator"
    text = "".join(f' {k}="{v}"' for k, v in attributes.items())
    element = f"<{spec.tag}{text}/>"
    path = _path(probe.row)[1:-1]  # between the root and the element
    if path[:1] == ("worldbody",):
        inner = path[2:] if path[1:2] == ("body",) else path[1:]
        for tag in reversed(inner):
            element = f"<{tag}{_extra(tag)}>{element}</{tag}>"
        return WORLD.format(body=element, section="")
    for tag in reversed(path):
        element = f"<{tag}{_extra(tag)}>{element}</{tag}>"
    return WORLD.format(body="", section=element)


def mujoco_error(xml: str, compile_model: bool) -> str | None:
    """MuJoCo's message refusing ``xml`` (compiling it, or only reading it), or ``None``."""
    try:
        if compile_model:
            mujoco.MjModel.from_xml_string(xml)
        else:
            mujoco.MjSpec.from_string(xml)
    except ValueError as error:
        return str(error)
    return None


def mujoco_loads(xml: str, compile_model: bool) -> bool:
    return mujoco_error(xml, compile_model) is None


def mujoco_takes(probe: Probe, keyword: str, compile_model: bool) -> bool:
    """Whether MuJoCo takes ``keyword`` on the probe's tag (a refusal :data:`CONTEXT`
    explains is not about the tag)."""
    error = mujoco_error(model_text(probe, keyword), compile_model)
    reason = CONTEXT.get((probe.id, keyword))
    if reason is not None:
        assert error is not None and reason in error, (
            f"{probe.id}={keyword!r}: MuJoCo no longer refuses it for {reason!r}: {error}")
        return mujoco_loads(model_text(probe, keyword), compile_model=False)
    return error is None


def library_assigns(probe: Probe, keyword: str) -> bool:
    """Whether the element of the probe model (read without the attribute) takes
    ``keyword`` by assignment."""
    model = mjcf.from_xml_string(model_text(probe, None))
    element = [e for e in model.iter_elements() if e.spec.row == probe.row][-1]
    attribute = element.spec.by_name[probe.attribute]
    extra = {element.spec.by_name[k].py_name: v
             for k, v in NEEDS.get((element.spec.tag, keyword), {}).items()}
    try:
        element.set_attributes(**{attribute.py_name: keyword}, **extra)
    except MjcfError:
        return False
    return True


def library_parses(xml: str) -> bool:
    try:
        mjcf.from_xml_string(xml)
    except MjcfError:
        return False
    return True


PROBES = shared_attributes()


def _params() -> list[object]:
    return [pytest.param(probe, id=probe.id) for probe in PROBES]


def test_the_shared_lists_are_found() -> None:
    """The probes cover the lists known to be shared (so the search cannot silently find
    nothing): the site's part of the geom's, actuators' and sensors' common lists."""
    ids = {probe.id for probe in PROBES}
    assert {"site@type", "geom@type", "camera@mode", "light@mode", "general@dyntype",
            "framepos@objtype", "pid@input", "motor@ctrllimited", "jointpos@interp"} <= ids
    site = next(p for p in PROBES if p.id == "site@type")
    assert {"plane", "hfield", "sphere", "mesh"} <= set(site.candidates)


@pytest.mark.parametrize("probe", _params())
def test_each_keyword_is_accepted_exactly_when_mujoco_loads_it(probe: Probe) -> None:
    compile_model = mujoco_loads(model_text(probe, None), compile_model=True)
    assert mujoco_loads(model_text(probe, None), compile_model=False), \
        f"the probe model of {probe.id} does not load without the attribute"
    taken = {k for k in probe.candidates if mujoco_takes(probe, k, compile_model)}
    assert taken, f"MuJoCo loads no keyword of {probe.id}: the probe model is wrong"
    assigned = {k for k in probe.candidates if library_assigns(probe, k)}
    parsed = {k for k in probe.candidates if library_parses(model_text(probe, k))}
    level = "compiles" if compile_model else "reads"
    assert assigned == taken, (
        f"{probe.id}: assignment takes {sorted(assigned)}, MuJoCo {level} {sorted(taken)}")
    assert parsed == taken, (
        f"{probe.id}: parsing takes {sorted(parsed)}, MuJoCo {level} {sorted(taken)}")


def test_the_site_is_probed_by_compiling() -> None:
    """The site's plane is refused by MuJoCo's compiler, not its reader: its probe must
    compile (else the test above would not see the difference)."""
    site = next(p for p in PROBES if p.id == "site@type")
    assert "<site" in model_text(site, None)
    assert mujoco_loads(model_text(site, None), compile_model=True)
    assert not mujoco_loads(model_text(site, "plane"), compile_model=True)
    assert mujoco_loads(model_text(site, "plane"), compile_model=False)

"""Storing a value and writing one are each decided in one place.

Storing: every route that sets an attribute (``add()``'s keywords, assignment,
``set_attributes()``, parsing, a name given from a file's stem) keeps the value as
``_tree._store`` says (the loops of building and parsing write its ``bare`` case, and call
its case for names, ``_store_name``, themselves); the first tests build the same model by
each route and compare what the tree holds: the values, the links, the references held as
names (and waiting for their element), the name tables, empty arrays left out, the model's
name. Every list of numbers of every row is then given an empty list on every route.

Writing: a text kept as read is written as read where its codec says so
(``Codec.keeps_read_text``, followed by ``Codec.write`` and by the exporter's write plan);
the last tests change that one declaration and check every export route follows.
"""

from __future__ import annotations

import html
import re
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import cast

import numpy as np
import pytest
from lxml import etree

import typed_mjcf as mjcf
from tests.compiled import patches
from typed_mjcf._core import codecs as _codecs
from typed_mjcf._core import tree as _tree
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.tree import Element, element_classes
from typed_mjcf.errors import MjcfError

# ---------------------------------------------------------------------------- storing

# The model each route makes, as (section, tag, attributes) in document order ("body": a
# child of the one body); a value "@name" is a reference given as the element of that name
# (parsing: the name). The motor names its joint before the joint exists (a name that
# waits, then links), the first sensor names a joint that exists (linked at once), the
# second names elements of namespaces other attributes name, the third a name nothing has
# (it stays a name, waiting); the keys set arrays that may be empty, and are when empty.
ELEMENTS: list[tuple[str, str, dict[str, object]]] = [
    ("actuator", "motor", {"name": "m", "joint": "j", "gear": (2.0,), "ctrlrange": (-1.0, 1.0)}),
    ("worldbody", "body", {"name": "b", "pos": (0.0, 0.0, 1.0), "quat": (1.0, 0.0, 0.0, 0.0)}),
    ("body", "joint", {"name": "j", "type": "hinge", "axis": (0.0, 1.0, 0.0), "limited": True,
                       "range": (-1.0, 1.0)}),
    ("body", "geom", {"type": "capsule", "size": (0.1,), "fromto": (0, 0, 0, 0, 0, 1),
                      "rgba": (1.0, 0.0, 0.0, 1.0), "contype": 1, "condim": 3}),
    ("body", "site", {"name": "s", "pos": (0.0, 0.0, 0.5)}),
    ("sensor", "jointpos", {"name": "p", "joint": "@j", "noise": 0.5}),
    ("sensor", "framepos", {"objtype": "site", "objname": "s", "reftype": "body",
                            "refname": "@b"}),
    ("sensor", "jointvel", {"joint": "nowhere"}),
    ("keyframe", "key", {"name": "k", "time": 1.0, "qpos": (0.25,), "act": ()}),
    ("keyframe", "key", {"name": "empty", "qvel": []}),
]
MODEL = "routes"


def _text(value: object) -> str:
    if isinstance(value, str):
        return value.removeprefix("@")
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, tuple | list):  # (no numbers: a space, as a file may have it)
        return " ".join(repr(float(x)) for x in cast("Sequence[float]", value)) or " "
    return repr(value)


def _parsed(resolve_references: bool = True) -> mjcf.RootElement:
    """The model read from MJCF text."""
    sections: dict[str, list[str]] = {}
    for section, tag, attributes in ELEMENTS:
        attrs = "".join(f' {k}="{_text(v)}"' for k, v in attributes.items())
        sections.setdefault(section, []).append(f"<{tag}{attrs}/>")
    body = sections.pop("body")
    sections["worldbody"] = [sections["worldbody"][0][:-2] + ">" + "".join(body) + "</body>"]
    text = "".join(f"<{name}>{''.join(parts)}</{name}>" for name, parts in sections.items())
    return mjcf.from_xml_string(f'<mujoco model="{MODEL}">{text}</mujoco>',
                                resolve_references=resolve_references)


def _python_values(model: mjcf.RootElement, attributes: dict[str, object]) -> dict[str, object]:
    values: dict[str, object] = {}
    for key, value in attributes.items():
        if isinstance(value, str) and value.startswith("@"):
            value = (model.find("body", value[1:]) if key == "refname"
                     else model.find("joint", value[1:]))
            assert value is not None
        values[key] = value
    return values


SetValues = Callable[[Element, dict[str, object]], None]


def _assigned(element: Element, values: dict[str, object]) -> None:
    for key, value in values.items():
        setattr(element, key, value)


def _set_together(element: Element, values: dict[str, object]) -> None:
    element.set_attributes(**values)


def _built(set_values: SetValues | None) -> mjcf.RootElement:
    """The model built in Python: by ``add()``'s keywords (``set_values`` None), else by
    adding each element bare and setting its values (the model's name too) with
    ``set_values``."""
    if set_values is None:
        model = mjcf.RootElement(model=MODEL)
    else:
        model = mjcf.RootElement()
        set_values(model, {"model": MODEL})
    body: Element | None = None
    for section, tag, attributes in ELEMENTS:
        parent = body if section == "body" else getattr(model, section)
        assert isinstance(parent, Element)
        values = _python_values(model, attributes)
        if set_values is None:
            element = parent.add(tag, **values)
        else:
            element = parent.add(tag)
            set_values(element, values)
        if tag == "body":
            body = element
    return model


ROUTES: dict[str, Callable[[], mjcf.RootElement]] = {
    "add() keywords": lambda: _built(None),
    "assignment": lambda: _built(_assigned),
    "set_attributes()": lambda: _built(_set_together),
    "parsing": _parsed,
}

# What a model holds, with elements by their place in document order: each element's tag
# and values (("link", place), ("name", text) or ("value", what it reads as)), the name
# tables, the references waiting for a name, the model's name.
Held = tuple[str, object]
State = tuple[list[tuple[str, dict[str, Held]]], dict[str, dict[str, int]],
              dict[tuple[str, str], list[tuple[int, str]]], str | None]


def _state(model: mjcf.RootElement) -> State:
    elements = list(model.iter_elements())
    place = {id(e): i for i, e in enumerate(elements)}

    def held(element: Element, attribute: AttributeSpec, stored: object) -> Held:
        if isinstance(stored, Element):
            return "link", place[id(stored)]
        if attribute.is_reference or attribute.kind == "id" or attribute.scope:
            return "name", stored
        return "value", np.asarray(_tree.read_value(element, attribute)).tolist()

    values = [(e.spec.tag, {name: held(e, e.spec.by_name[name], stored)
                            for name, stored in sorted(_tree.values(e).items())})
              for e in elements]
    scope = _tree.scope_of(model)
    tables = {namespace: {name: place[id(named)] for name, named in table.items()
                          if isinstance(named, Element)}
              for namespace, table in scope.tables.items() if table}
    waiting = {key: [(place[id(e)], a.name) for e, a in entries
                     if isinstance(e, Element) and isinstance(a, AttributeSpec)]
               for key, entries in scope.waiting.items() if entries}
    return values, tables, waiting, scope.name


@pytest.mark.parametrize("route", [r for r in ROUTES if r != "add() keywords"])
def test_every_route_stores_the_same_model(route: str) -> None:
    expected = _state(_built(None))
    found = _state(ROUTES[route]())
    for part, (want, got) in enumerate(zip(expected, found, strict=True)):
        assert got == want, (route, ["values", "name tables", "waiting", "model"][part])


def test_the_model_compared_holds_what_it_was_asked_to() -> None:
    """Every kind of value ``_store`` tells apart, as asked (so the comparison above
    compares something)."""
    values, tables, waiting, name = _state(_built(None))
    tags = [tag for tag, _ in values]
    by_tag = {tag: held for tag, held in reversed(values)}  # (the first key)
    assert by_tag["motor"] == {"ctrlrange": ("value", [-1.0, 1.0]), "gear": ("value", [2.0]),
                               "joint": ("link", tags.index("joint")), "name": ("name", "m")}
    assert by_tag["jointpos"]["joint"] == ("link", tags.index("joint"))
    assert by_tag["framepos"]["objname"] == ("link", tags.index("site"))
    assert by_tag["framepos"]["refname"] == ("link", tags.index("body"))
    assert by_tag["jointvel"] == {"joint": ("name", "nowhere")}
    assert waiting == {("joint", "nowhere"): [(tags.index("jointvel"), "joint")]}
    assert tables["joint"] == {"j": tags.index("joint")} and "k" in tables["key"]
    assert name == MODEL
    keys = [held for tag, held in values if tag == "key"]
    assert [sorted(k) for k in keys] == [["name", "qpos", "time"], ["name"]]  # empty: absent
    assert all(element_classes()["Key"].spec.by_key[a].lo == 0 for a in ("act", "qvel"))


def test_references_read_without_linking_stay_names_until_resolved() -> None:
    """``resolve_references=False`` keeps names as names, waiting for nothing; linking them
    later gives what every other route stores (but for the name nothing has: no waiting)."""
    kept = _parsed(resolve_references=False)
    jointpos = kept.find("sensor", "p")
    assert jointpos is not None
    assert _tree.values(jointpos)["joint"] == "j"
    assert not _tree.scope_of(kept).waiting
    kept.resolve_references()
    values, tables, waiting, name = _state(kept)
    expected = _state(_built(None))
    assert (values, tables, name) == (expected[0], expected[1], expected[3])
    assert waiting == {}


def test_a_refused_value_on_any_route_leaves_the_model_as_it_was() -> None:
    model = _built(None)
    before = _state(model)
    found, site = model.find("body", "b"), model.find("site", "s")
    assert found is not None and site is not None
    body = cast(Element, found)  # (values of the wrong type: the untyped signatures)
    refused: list[Callable[[], object]] = [
        lambda: body.add("joint", name="new", axis=(1, 2)),  # a value: nothing claimed
        lambda: body.add("joint", name="n/a"),  # the name itself
        lambda: model.actuator.add("motor", joint="later", name="m"),  # the name is taken
        lambda: body.set_attributes(name="renamed", pos=(1, 2)),
        lambda: setattr(site, "name", "n/a"),
    ]
    for refuse in refused:
        with pytest.raises(MjcfError):
            refuse()
        assert _state(model) == before, refuse


def _array_attributes() -> Iterator[tuple[type[Element], AttributeSpec]]:
    """Every list of numbers of every row (as the installed MuJoCo types it)."""
    for cls in element_classes().values():
        for attribute in cls.spec.attributes.values():
            if attribute.direct and attribute.is_array and attribute.kind in ("int", "real"):
                yield cls, attribute


def _routes_of_an_empty_list(cls: type[Element], attribute: AttributeSpec
                             ) -> Iterator[tuple[str, Callable[[], Element]]]:
    """Each route giving ``attribute`` an empty list, on a new element of ``cls`` (one
    holding a value first, for the routes that change a value), as a function returning it."""
    root = mjcf.RootElement()
    some = [1] * max(attribute.lo, 1)

    def new(value: object = None) -> Element:
        element = _tree._create(cls, root)  # (not among its parent's children: no row
        if value is not None:  # needs a path from the root)
            element._init_attributes({attribute.py_name: value})
        return element

    def built() -> Element:
        element = new()
        element._init_attributes({attribute.py_name: []})
        return element

    def assigned() -> Element:
        element = new(some)
        setattr(element, attribute.py_name, [])
        return element

    def set_together() -> Element:
        element = new(some)
        element.set_attributes(**{attribute.py_name: []})
        return element

    def parsed() -> Element:
        element = new()
        rest = _tree.assign_texts(element, [(attribute.name, " ")])  # (a file's empty list)
        if rest is not None and rest[0][3] is not None:
            raise rest[0][3]
        return element

    def parsed_again() -> Element:
        element = new(some)
        _tree.assign_text(element, attribute, " ")
        return element

    yield from [("built", built), ("assigned", assigned), ("set_attributes", set_together),
                ("parsed", parsed), ("parsed over a value", parsed_again)]


def test_an_empty_list_of_numbers_is_absent_on_every_route_or_refused() -> None:
    """``_store``'s rule for every list of numbers of every row, on every route (the loops
    of ``add()`` and parsing write a ``bare`` attribute without calling ``_store``: so the
    flag holds only where an empty list cannot be given): a list that may hold no numbers
    stored empty is absent, as MuJoCo reads it; every other refuses it."""
    may_be_empty = refused = 0
    for cls, attribute in _array_attributes():
        for route, give in _routes_of_an_empty_list(cls, attribute):
            if attribute.lo > 0:
                with pytest.raises((MjcfError, _codecs.Rejected)):
                    give()
                refused += 1
            else:
                assert attribute.name not in _tree.values(give()), (cls, attribute, route)
                may_be_empty += 1
    assert may_be_empty >= 5 * 100 and refused >= 5 * 400  # (118 and 453 lists today)


def test_only_lists_that_may_hold_no_numbers_are_direct_and_not_bare() -> None:
    """``bare``: direct, and never empty; the rest of the direct attributes are the lists
    of numbers the test above stores empty."""
    for cls in element_classes().values():
        for attribute in cls.spec.attributes.values():
            empty_may_come = attribute.is_array and attribute.lo == 0
            assert attribute.bare == (attribute.direct and not empty_may_come), attribute
            if empty_may_come:
                assert attribute.kind in ("int", "real"), attribute


# ---------------------------------------------------------------------------- writing

FILE = """<mujoco model="part">
  <worldbody>
    <body name="b" pos="0 0 1.50">
      <joint name="j" type="slide"/>
      <geom name="g" size="0.10" rgba="1 0 0 1.0"/>
      <site name="s" size=".020"/>
    </body>
  </worldbody>
  <sensor><jointpos name="p" joint="j" noise="0.0"/></sensor>
</mujoco>
"""
SPELLED = ("1.50", "0.10", "1.0", ".020", "0.0")  # as the file spells them
CANONICAL = ("1.5", "0.1", "0.02")  # as the codecs spell the same numbers


def _export_routes(tmp_path: Path) -> Iterator[tuple[str, str]]:
    """Every route that writes a model read from a file, with its text."""
    model = mjcf.from_xml_string(FILE)
    body = model.find("body", "b")
    site = model.find("site", "s")
    assert body is not None and site is not None
    yield "to_xml_string", model.to_xml_string()
    yield "to_xml_string, not pretty", model.to_xml_string(pretty_print=False)
    yield "str()", str(body) + str(site)
    yield "to_xml", etree.tostring(model.to_xml()).decode()
    yield "get_attribute_xml_string", body.get_attribute_xml_string("pos") or ""
    folder = tmp_path / "out"
    mjcf.export_with_assets(model, folder, "m.xml")
    yield "export_with_assets", (folder / "m.xml").read_text(encoding="utf-8")
    # the values of an attached model (written in its scope)
    parent = mjcf.from_xml_string('<mujoco model="parent"><worldbody><site name="mount"/>'
                                  '</worldbody></mujoco>')
    mount = parent.find("site", "mount")
    assert mount is not None
    mount.attach(mjcf.from_xml_string(FILE))
    yield "composed model", parent.to_xml_string()
    # an element whose text needs escaping (the escaped path of the fast writer)
    escaped = mjcf.from_xml_string(FILE)
    geom = escaped.find("geom", "g")
    assert geom is not None
    geom.name = 'g"<&'
    yield "escaped", str(geom)


def _numbers(text: str) -> set[str]:
    return set(re.findall(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?![\w.])", text))


def _no_plans(monkeypatch: pytest.MonkeyPatch) -> None:
    """Forget the write plans made so far (they are made once per row from the codecs)."""
    for cls in element_classes().values():
        monkeypatch.setattr(cls.spec, "plans", {})


def test_by_default_every_route_writes_numbers_as_the_file_spells_them(
        tmp_path: Path) -> None:
    for route, text in _export_routes(tmp_path):
        if route == "get_attribute_xml_string":
            assert text == "0 0 1.50", route
            continue
        assert _numbers(text) & set(SPELLED), (route, text)
        assert not _numbers(text) & {"1.5", "0.02"}, (route, text)


@patches("_core.codecs")
def test_a_codec_that_rewrites_what_it_read_is_followed_by_every_route(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    for codec in (_codecs.RealCodec, _codecs.ArrayCodec):
        monkeypatch.setattr(codec, "keeps_read_text", False)
    _no_plans(monkeypatch)
    for route, text in _export_routes(tmp_path):
        assert not _numbers(text) & set(SPELLED), (route, text)
        assert _numbers(text) & set(CANONICAL), (route, text)


def _shouted(codec: _codecs.Codec, stored: object, fmt: _codecs.Format) -> str:
    return str(stored).upper()


@patches("_core.codecs")
def test_a_name_codec_that_rewrites_names_is_followed_by_every_route(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Names and references are written by their codecs too (here: in capitals), in the
    fast writer, the escaped one and for an attached model's scope."""
    for codec in (_codecs.IdentifierCodec, _codecs.ReferenceCodec):
        monkeypatch.setattr(codec, "keeps_read_text", False)
        monkeypatch.setattr(codec, "write", _shouted)
    _no_plans(monkeypatch)
    for route, text in _export_routes(tmp_path):
        if route == "get_attribute_xml_string":
            continue  # (a number)
        names = {html.unescape(name).rsplit("/", 1)[-1]  # (a scope's prefix is no name)
                 for name in re.findall(r'\b(?:name|joint)="([^"]*)"', text)}
        assert names - {""}, route
        assert all(name == name.upper() for name in names), (route, names)


@patches("_core.codecs")
def test_a_number_codec_follows_its_declaration() -> None:
    """What the exporter's plan reads (``keeps_read_text``) is what ``write`` does: flipped,
    the number codecs rewrite a text they kept as read."""
    real = _codecs.make_codec("real", dtype="double", is_array=False, lo=1, hi=1,
                              keywords=(), pattern=None)
    array = _codecs.make_codec("real", dtype="double", is_array=True, lo=3, hi=3,
                               keywords=(), pattern=None)
    verbatim = _codecs.Format()
    for codec, text, canonical in ((real, "0.50", "0.5"), (array, "0 0 1.50", "0 0 1.5")):
        kept = codec.parse(text)
        assert kept == text and codec.write(kept, verbatim) is kept
        with pytest.MonkeyPatch.context() as patch:
            patch.setattr(type(codec), "keeps_read_text", False)
            assert codec.write(kept, verbatim) == canonical

"""An attribute's type follows the release in use (``typed_mjcf._releases.gating``): where an older
release types it otherwise than the newest (kind, value count, keywords, default, namespace;
the generated ``TYPES`` table), its spec, codec and default are that release's, on every
route (assignment, parse, export, validate); a value only another release takes is refused
naming that release. The tests read the table, so they check whichever release is in use:
the installed one, or another through ``tests.runtime.release_driver`` (test_release_driven
runs them so for every older release on the newest MuJoCo; ``nox -s releases`` on each
older MuJoCo itself)."""

from __future__ import annotations

import os
from collections import deque
from typing import cast

import pytest

import typed_mjcf as mjcf
from tests.runtime.release_driver import RELEASE_VARIABLE
from typed_mjcf._core import codecs as _codecs
from typed_mjcf._core.codecs import Rejected
from typed_mjcf._core.grammar import AttributeSpec, ElementSpec
from typed_mjcf._core.rows import ReleaseType
from typed_mjcf._core.tree import Element, element_classes
from typed_mjcf._generated.releases import KEYWORDS, RELEASES, REMOVED, TYPES
from typed_mjcf._releases import gating as _releases
from typed_mjcf.errors import InvalidValueError, ParseError

CLASSES = {cls.spec.row: cls for cls in element_classes().values()}
ROOT = mjcf.RootElement.spec
RETYPED = [(row, name, by_release) for row, attributes in sorted(TYPES.items())
           for name, by_release in sorted(attributes.items())
           if row in CLASSES and name in CLASSES[row].spec.by_name]


def test_the_release_in_use_is_the_one_asked_for() -> None:
    asked = os.environ.get(RELEASE_VARIABLE)
    if asked:
        assert _releases.RELEASE == _releases.INSTALLED == asked
    else:
        assert _releases.INSTALLED is None or _releases.RELEASE == _releases.choose(
            _releases.INSTALLED)


def test_the_table_types_only_what_differs_and_only_for_older_releases() -> None:
    assert TYPES, "the releases covered type some attribute otherwise (headlight@active)"
    for row, attributes in TYPES.items():
        for name, by_release in attributes.items():
            assert RELEASES[-1] not in by_release, (row, name)
            assert set(by_release) <= set(RELEASES), (row, name)
            assert name not in KEYWORDS.get(row, {}), (row, name)  # one table per attribute


@pytest.mark.parametrize(("row", "name", "by_release"), RETYPED,
                         ids=[f"{row}@{name}" for row, name, _ in RETYPED])
def test_an_attribute_has_the_type_of_the_release_in_use(
        row: str, name: str, by_release: dict[str, ReleaseType]) -> None:
    cls = CLASSES[row]
    attribute = cls.spec.by_name[name]
    if _releases.RELEASE in by_release:
        typed = by_release[_releases.RELEASE]
        kind, dtype, arity, words, numbers = (typed.kind, typed.dtype, typed.arity,
                                              typed.keywords, typed.numbers)
        default, namespace = typed.default, typed.namespace
        assert _releases.newest_type(cls.spec, attribute) is not attribute
        assert attribute.kind == kind and attribute.default == default
        assert attribute.namespace == namespace and attribute.keywords == words
        assert attribute.numbers == numbers
        assert dtype is None or attribute.dtype == dtype
        assert (attribute.lo, attribute.hi) == (arity if arity is not None else (1, 1))
        assert attribute.is_reference == (kind == "ref")
    else:  # the newest's type, untouched
        assert _releases.newest_type(cls.spec, attribute) is attribute
        assert all(attribute.kind != typed.kind or attribute.default != typed.default
                   or attribute.namespace != typed.namespace or attribute.numbers != typed.numbers
                   for typed in by_release.values())
    assert (attribute in cls.spec.references) == attribute.is_reference
    prop = vars(cls)[attribute.py_name]
    assert prop.spec is attribute and prop.codec is attribute.codec  # the property follows


def _path(row: str) -> list[ElementSpec]:
    """The rows from the root's down to ``row``'s, by the children each takes."""
    parents: dict[str, ElementSpec | None] = {ROOT.row: None}
    specs = {ROOT.row: ROOT}
    queue = deque([ROOT])
    while queue:
        spec = queue.popleft()
        for child in spec.children.values():
            below = child.cls.spec
            if below.row not in parents:
                parents[below.row], specs[below.row] = spec, below
                queue.append(below)
    path = [specs[row]]
    while (parent := parents[path[-1].row]) is not None:
        path.append(parent)
    return path[::-1]


def _xml(row: str, attributes: str = "", before: str = "") -> str:
    tags = [spec.tag for spec in _path(row)]
    inner = f"<{tags[-1]} {attributes}/>"
    for tag in reversed(tags[1:-1]):
        inner = f"<{tag}>{inner}</{tag}>"
    return f"<{tags[0]}>{before}{inner}</{tags[0]}>"


def _element(model: Element, row: str) -> Element:
    element = model
    for spec in _path(row)[1:]:
        found: object = getattr(element, element.spec.children[spec.tag].py_name)
        element = found if isinstance(found, Element) else cast("list[Element]", found)[0]
    return element


def _values(by_release: dict[str, ReleaseType], spec: ElementSpec,
            attribute: AttributeSpec) -> list[str]:
    """Each release's default of the attribute: texts some release takes."""
    newest = _releases.newest_type(spec, attribute)
    found = [typed.default for typed in by_release.values() if typed.default is not None]
    return found + ([newest.default] if newest.default is not None else [])


@pytest.mark.parametrize(("row", "name", "by_release"), RETYPED,
                         ids=[f"{row}@{name}" for row, name, _ in RETYPED])
def test_a_value_of_another_release_is_refused_naming_it_and_its_own_kept(
        row: str, name: str, by_release: dict[str, ReleaseType]) -> None:
    spec = CLASSES[row].spec
    attribute = spec.by_name[name]
    values = _values(by_release, spec, attribute)
    if not values:
        pytest.skip(f"{row}@{name} has no default in any release to try")
    for text in values:
        model = mjcf.from_xml_string(_xml(row))
        element = _element(model, row)
        if not _takes(spec, attribute, _releases.RELEASE, text):
            having = [r for r in RELEASES if _takes(spec, attribute, r, text)]
            assert having and _releases.RELEASE not in having
            message = (f"{text!r} for {attribute.py_name!r} of <{spec.tag}> "
                       f"(needs MuJoCo >= {having[0]}|is in MuJoCo {', '.join(having)} only); "
                       f"installed {_releases.INSTALLED}; expected ")
            with pytest.raises(InvalidValueError, match=message):
                setattr(element, attribute.py_name, text)
            assert getattr(element, attribute.py_name) is None  # unchanged
            with pytest.raises(ParseError, match=message):
                mjcf.from_xml_string(_xml(row, f'{name}="{text}"'))
            continue
        setattr(element, attribute.py_name, text)  # the release's own: kept on every route
        again = mjcf.from_xml_string(model.to_xml_string())
        assert _element(again, row).get_attributes()[attribute.py_name] == \
            element.get_attributes()[attribute.py_name]
        # as given, or the keyword a number MuJoCo reads as one is (its canonical spelling)
        written = attribute.codec.write(attribute.codec.accept(text), _codecs.DEFAULT_FORMAT)
        assert written == text or (written, int(text)) in attribute.numbers
        assert f'{name}="{written}"' in model.to_xml_string()


def _takes(spec: ElementSpec, attribute: AttributeSpec, release: str, text: str) -> bool:
    codec = _releases.release_codec(spec, _releases.newest_type(spec, attribute), release)
    try:
        codec.accept(text)
    except Rejected:
        return False
    return True


def test_headlight_active_is_the_release_s() -> None:
    """MuJoCo 3 reads <headlight active> as an int (default 1), MuJoCo 4 as a keyword
    (false|true|auto, default auto): a model says what the release in use reads."""
    by_release = TYPES["headlight"]["active"]
    model = mjcf.RootElement()
    headlight = model.visual.headlight
    attribute = headlight.spec.by_name["active"]
    if _releases.RELEASE in by_release:
        assert attribute.default == "1" and attribute.kind == "int"
        with pytest.raises(InvalidValueError, match="'auto' for 'active' of <headlight> needs "
                           f"MuJoCo >= {RELEASES[-1]}; installed {_releases.INSTALLED}; "
                           "expected"):
            headlight.active = "auto"
        setattr(headlight, "active", 0)  # the typed API is the newest's: a keyword
        assert headlight.get_attributes()["active"] == 0
        assert '<headlight active="0"/>' in model.to_xml_string()
    else:
        assert attribute.default == "auto" and attribute.kind == "keyword"
        with pytest.raises(InvalidValueError, match=f"'3' for 'active' of <headlight> is in "
                           f"MuJoCo {', '.join(by_release)} only"):
            setattr(headlight, "active", "3")
        setattr(headlight, "active", "1")  # what MuJoCo 4 still reads: the keyword true
        assert '<headlight active="true"/>' in model.to_xml_string()
        headlight.active = "auto"
        assert '<headlight active="auto"/>' in model.to_xml_string()
    _compiles_when_installed(model)


def test_flex_material_is_a_reference_where_the_release_says_so() -> None:
    by_release = TYPES["flex"]["material"]
    xml = _xml("flex", 'name="f" dim="1" body="b" vertex="0 0 0 1 0 0" element="0 1" material="m"',
               before='<asset><material name="m"/></asset>').replace(
        "<deformable>", '<worldbody><body name="b"/></worldbody><deformable>')
    model = mjcf.from_xml_string(xml)
    flex = _element(model, "flex")
    if _releases.RELEASE in by_release:  # one material, by name: a reference
        assert flex.get_attributes()["material"] is model.asset.material[0]
        model.asset.material[0].name = "renamed"
        assert 'material="renamed"' in model.to_xml_string()
        dangling = mjcf.from_xml_string(xml.replace('name="m"', 'name="other"'))
        assert any(f.path == "deformable/flex[f]" and "material" in f.message
                   for f in dangling.validate())  # names no material
    else:  # a free text (MuJoCo 4 lists materials)
        assert flex.get_attributes()["material"] == "m"
        listed = mjcf.from_xml_string(xml.replace('material="m"', 'material="m other"'))
        assert _element(listed, "flex").get_attributes()["material"] == "m other"
    assert not model.validate()


def _compiles_when_installed(model: mjcf.RootElement) -> None:
    """Compiled by MuJoCo when the release in use is the installed MuJoCo's."""
    import mujoco

    if mujoco.__version__ != _releases.INSTALLED:
        return  # the release is pretended (release_driver): the MuJoCo here reads another
    mujoco.MjModel.from_xml_string(model.to_xml_string())


REMOVED_CHILDREN = [(row, tag, having) for row, children in sorted(REMOVED.items())
                    for tag, having in sorted(children.items()) if row in CLASSES]


@pytest.mark.parametrize(("row", "tag", "having"), REMOVED_CHILDREN,
                         ids=[f"{row}/{tag}" for row, tag, _ in REMOVED_CHILDREN])
def test_a_child_only_older_releases_have_is_refused_naming_the_releases(
        row: str, tag: str, having: tuple[str, ...]) -> None:
    """Rows only older releases have (MuJoCo 3's <composite>) have no class: on a release
    without them the message says when they went; on one with them, that typed-mjcf has no
    bindings for them (the typed API is the newest's)."""
    gone = RELEASES[RELEASES.index(having[-1]) + 1]
    if _releases.RELEASE in having:
        expected = f"is in MuJoCo {', '.join(having)} only, and typed-mjcf has no bindings"
    elif _releases.version_key(_releases.RELEASE) > _releases.version_key(having[-1]):
        expected = f"was removed in MuJoCo {gone}"
    else:  # came after the release in use, and went
        expected = f"is in MuJoCo {', '.join(having)} only"
    assert tag not in CLASSES[row].spec.children
    with pytest.raises(ParseError, match=f"<{tag}> is not a legal child of <{CLASSES[row].spec.tag}> "
                       rf"\(.*\): it {expected}.*; installed {_releases.INSTALLED}"):
        mjcf.from_xml_string(_xml(row).replace(f"<{CLASSES[row].spec.tag} />",
                                               f"<{CLASSES[row].spec.tag}><{tag}/>"
                                               f"</{CLASSES[row].spec.tag}>"))

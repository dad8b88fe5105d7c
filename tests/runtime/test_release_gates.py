"""The runtime follows the installed MuJoCo's grammar (``typed_mjcf._releases.gating``): what that
release lacks of the newest's (the typing surface) is refused, naming the release that has
it; what it has is accepted. The tests read the generated table, so they check whichever
release is installed (``nox -s releases`` runs them on the older ones)."""

from __future__ import annotations

import os

import pytest

import typed_mjcf as mjcf
from tests.runtime.release_driver import RELEASE_VARIABLE
from typed_mjcf._core.tree import Attribute, element_classes
from typed_mjcf._generated.releases import ATTRIBUTES, CHILDREN, KEYWORDS, RELEASES
from typed_mjcf._releases import gating as _releases
from typed_mjcf.errors import (
    IllegalChildError,
    InvalidValueError,
    ParseError,
    UnknownAttributeError,
)

CLASSES = {cls.spec.row: cls for cls in element_classes().values()}


def test_the_release_in_use_is_the_newest_covered_not_newer_than_the_installed() -> None:
    import mujoco  # the installed MuJoCo itself, against the metadata read at import

    pretended = os.environ.get(RELEASE_VARIABLE)  # tests.runtime.release_driver
    assert _releases.INSTALLED == (pretended or mujoco.__version__)
    assert _releases.RELEASE == _releases.choose(_releases.INSTALLED)
    assert _releases.RELEASE in RELEASES


def test_choosing_a_release() -> None:
    oldest, newest = RELEASES[0], RELEASES[-1]
    assert [_releases.choose(r) for r in RELEASES] == list(RELEASES)
    assert _releases.choose(None) == newest  # no MuJoCo: the typing surface
    assert _releases.choose("0.1.0") == oldest  # older than any: the oldest's grammar
    assert _releases.choose(newest + ".1") == newest  # a patch above the newest
    if len(RELEASES) > 1:  # between two releases: the older one's grammar
        assert _releases.choose(RELEASES[-2] + ".1") == RELEASES[-2]
    assert not _releases.covered("0.1.0")
    assert _releases.covered(newest)


def test_versions_says_what_is_covered_and_what_is_installed() -> None:
    text = _releases.describe()
    assert ", ".join(RELEASES) in text
    assert f"installed: {_releases.INSTALLED}" in text


def test_the_table_gates_only_what_some_release_lacks() -> None:
    for row, attributes in ATTRIBUTES.items():
        for name, having in attributes.items():
            assert having[-1] == RELEASES[-1], (row, name)  # the newest has all it types
            assert set(having) < set(RELEASES), (row, name)
    for row, children in CHILDREN.items():
        for tag, having in children.items():
            assert set(having) < set(RELEASES), (row, tag)


GATED = [(row, name, having) for row, attributes in sorted(ATTRIBUTES.items())
         for name, having in sorted(attributes.items()) if row in CLASSES]


@pytest.mark.parametrize(("row", "name", "having"), GATED,
                         ids=[f"{row}@{name}" for row, name, _ in GATED])
def test_an_attribute_is_there_exactly_in_the_releases_that_have_it(
        row: str, name: str, having: tuple[str, ...]) -> None:
    spec = CLASSES[row].spec
    if _releases.RELEASE in having:
        assert name in spec.by_name
        assert _releases.note(spec, name) is None
    else:
        assert name not in spec.by_name
        assert all(a.name != name for a in spec.attributes.values())
        note = _releases.note(spec, name)
        assert note is not None and having[0] in note and f"installed {_releases.INSTALLED}" in note
        assert not any(isinstance(member, Attribute) and member.name == name
                       for member in vars(CLASSES[row]).values())  # the property went too


def _gated_pairs() -> list[tuple[str, str, tuple[str, ...]]]:
    return [(row, tag, having) for row, children in sorted(CHILDREN.items())
            for tag, having in sorted(children.items()) if row in CLASSES]


@pytest.mark.parametrize(("row", "tag", "having"), _gated_pairs())
def test_a_child_is_there_exactly_in_the_releases_that_have_it(
        row: str, tag: str, having: tuple[str, ...]) -> None:
    cls = CLASSES[row]
    if _releases.RELEASE in having:
        assert tag in cls.spec.children
        assert callable(getattr(cls, "add_" + tag))
    else:
        assert tag not in cls.spec.children
        assert not hasattr(cls, "add_" + tag)
        assert _releases.note(cls.spec, tag) is not None


def test_keywords_are_the_release_s() -> None:
    for row, attributes in KEYWORDS.items():
        if row not in CLASSES:
            continue
        for name, by_release in attributes.items():
            attribute = CLASSES[row].spec.by_name.get(name)
            if attribute is None:
                continue
            if _releases.RELEASE in by_release:
                assert attribute.keywords == by_release[_releases.RELEASE], (row, name)
            else:
                assert set(by_release.values()) != {attribute.keywords}, (row, name)


def _first_gone_attribute() -> tuple[str, str, tuple[str, ...]] | None:
    """A gated attribute of <joint>-like rows the release in use lacks, if any."""
    return next(((row, name, having) for row, name, having in GATED
                 if _releases.RELEASE not in having and row == CLASSES[row].spec.tag
                 and CLASSES[row].spec.tag in {"joint", "geom", "site", "body", "camera"}),
                None)


def test_a_missing_attribute_is_refused_on_every_route_naming_the_release() -> None:
    found = _first_gone_attribute()
    if found is None:
        pytest.skip(f"MuJoCo {_releases.RELEASE} lacks no attribute of the rows this test "
                    "builds")
    row, name, having = found
    model = mjcf.RootElement()
    body = model.worldbody.add_body(name="b")
    element = body if row == "body" else body.add(row)
    expected = f"needs MuJoCo >= {having[0]}"
    with pytest.raises(UnknownAttributeError, match=expected):
        element.set_attributes(**{name: "1"})
    with pytest.raises(UnknownAttributeError, match=expected):
        setattr(element, name, "1")
    assert name not in element.get_attributes()  # the element is unchanged
    xml = (f'<mujoco><worldbody><body name="b" {name}="1"/></worldbody></mujoco>'
           if row == "body" else
           f'<mujoco><worldbody><body><{row} {name}="1"/></body></worldbody></mujoco>')
    with pytest.raises(ParseError, match=expected):
        mjcf.from_xml_string(xml)
    import mujoco

    if mujoco.__version__ == _releases.INSTALLED:  # not a pretended release
        with pytest.raises(ValueError, match=name):  # the installed MuJoCo lacks it too
            mujoco.MjSpec.from_string(xml)


def test_a_missing_child_is_refused_naming_the_release() -> None:
    root = CLASSES[mjcf.RootElement.spec.row].spec.row
    gone = [(row, tag, having) for row, tag, having in _gated_pairs()
            if _releases.RELEASE not in having and row in {root, "actuator", "equality"}]
    if not gone:
        pytest.skip(f"MuJoCo {_releases.RELEASE} lacks no child of the sections this test "
                    "builds")
    row, tag, having = gone[0]
    model = mjcf.RootElement()
    section = model if row == root else getattr(model, row)
    with pytest.raises(IllegalChildError, match=f"needs MuJoCo >= {having[0]}"):
        section.add(tag)
    xml = (f"<mujoco><{tag}/></mujoco>" if row == root else
           f"<mujoco><{row}><{tag}/></{row}></mujoco>")
    with pytest.raises(ParseError, match=f"needs MuJoCo >= {having[0]}"):
        mjcf.from_xml_string(xml)
    import mujoco

    if mujoco.__version__ == _releases.INSTALLED:  # not a pretended release
        with pytest.raises(ValueError, match=tag):  # the installed MuJoCo lacks it too
            mujoco.MjSpec.from_string(xml)


def test_a_keyword_of_another_release_is_refused_naming_it() -> None:
    spec = CLASSES["general"].spec
    for name, by_release in sorted(KEYWORDS.get("general", {}).items()):
        words = by_release.get(_releases.RELEASE)
        attribute = spec.by_name[name]
        newer = [w for w in _releases.newest_keywords(spec, attribute) if w not in (words or ())]
        if words is None or not newer:
            continue
        element = mjcf.RootElement().actuator.add_general()
        with pytest.raises(InvalidValueError, match=f"{newer[0]!r} for {name!r} of <general> "
                           "needs MuJoCo >="):
            setattr(element, name, newer[0])
        assert getattr(element, name) is None
        return
    pytest.skip(f"no <general> keyword is missing from MuJoCo {_releases.RELEASE}")

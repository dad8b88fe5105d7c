"""codegen/releases.py: what an older release's grammar lacks of the newest's, as the table
the runtime applies and as the attribute docs say it."""

from __future__ import annotations

import copy
from pathlib import Path

import pytest

from codegen import ir, releases, render
from codegen.errors import FactsError
from codegen.facts import load_facts
from codegen.rows import ReleaseType


def _older(newest: ir.Schema, version: str) -> ir.Schema:
    old = copy.deepcopy(newest)
    old.mujoco_version = version
    return old


def test_gates_list_exactly_what_an_older_release_lacks() -> None:
    newest = ir.load()
    old = _older(newest, "3.0.0")
    joint = old.elements["joint"]
    joint.attributes = [a for a in joint.attributes if a.name != "damping"]
    actuator = old.elements["actuator"]
    actuator.children = [c for c in actuator.children if c.element != "motor"]
    joint_type = joint.attribute("type")
    assert joint_type.enum is not None
    old.enums[joint_type.enum].values = old.enums[joint_type.enum].values[:-1]
    gates = releases.gates(newest, {"3.0.0": old, "4.0.0": _older(newest, "9.0.0")})
    assert gates.releases == ("3.0.0", newest.mujoco_version)  # not-older files left out
    assert gates.attributes == {"joint": {"damping": (newest.mujoco_version,)}}
    assert gates.children == {"actuator": {"motor": (newest.mujoco_version,)}}
    keywords = tuple(newest.enums[joint_type.enum].keywords[:-1])
    users = {row: {a.name: {"3.0.0": keywords}} for row, el in newest.elements.items()
             for a in el.attributes if a.enum == joint_type.enum}  # <joint> and its default
    assert "joint" in users and len(users) >= 2
    assert gates.keywords == users


def test_the_table_is_the_gates_as_python() -> None:
    newest = ir.load()
    old = _older(newest, "3.0.0")
    old.elements["geom"].attributes = old.elements["geom"].attributes[1:]
    gates = releases.gates(newest, {"3.0.0": old})
    namespace: dict[str, object] = {}
    exec(releases.render_table(gates, newest.mujoco_version), namespace)  # noqa: S102
    assert namespace["RELEASES"] == gates.releases
    assert namespace["ATTRIBUTES"] == gates.attributes
    assert namespace["CHILDREN"] == {} and namespace["KEYWORDS"] == {}


def test_availability_in_words() -> None:
    covered = ("3.3.7", "3.17.0", "4.0.0")
    assert releases.availability(("3.17.0", "4.0.0"), covered) == "MuJoCo >= 3.17.0"
    assert releases.availability(("3.3.7", "4.0.0"), covered) == "MuJoCo 3.3.7, 4.0.0 only"


def test_an_attribute_s_doc_names_the_releases_that_have_it() -> None:
    newest = ir.load()
    name = newest.elements["joint"].attributes[-1].name
    old = _older(newest, "3.0.0")
    old.elements["joint"].attributes = old.elements["joint"].attributes[:-1]
    files = render.render(newest, older={"3.0.0": old})
    note = f"in MuJoCo >= {newest.mujoco_version}."
    line = next(line for line in files["elements.py"].splitlines()
                if line.strip().startswith(f"A({name!r}") and "'joint'" not in line
                and note in line)
    assert note in line
    stub = files["elements.pyi"]
    assert f"``{name}``: " in stub and note in stub


def test_version_order_is_numeric() -> None:
    assert sorted(["4.0.0", "3.17.0", "3.3.7"], key=releases.version_key) == [
        "3.3.7", "3.17.0", "4.0.0"]


def test_gates_list_each_release_s_type_where_more_than_keywords_differ() -> None:
    newest = ir.load()
    old = _older(newest, "3.0.0")
    damping = old.elements["joint"].attribute("damping")
    damping.kind, damping.dtype, damping.arity, damping.default = "int", "int", (1, 2), "3"
    gates = releases.gates(newest, {"3.0.0": old})
    assert gates.types == {"joint": {"damping": {"3.0.0": {
        "kind": "int", "arity": (1, 2), "default": "3"}}}}
    assert gates.keywords == {} and gates.attributes == {}
    namespace: dict[str, object] = {}
    exec(releases.render_table(gates, newest.mujoco_version), namespace)  # noqa: S102
    assert namespace["TYPES"] == {"joint": {"damping": {"3.0.0": ReleaseType(
        "int", arity=(1, 2), default="3")}}}
    notes = releases.notes(gates)
    assert notes["joint"]["damping"] == 'MuJoCo 3.0.0: int[1..2], default "3"'


def test_gates_list_a_release_reading_no_numbers_for_keywords() -> None:
    """A release whose reader takes only the keywords (no ``numbers``) types the attribute
    otherwise: its codec refuses the number the newest reads."""
    newest = ir.load()
    old = _older(newest, "3.0.0")
    assert newest.elements["headlight"].attribute("active").numbers
    old.elements["headlight"].attribute("active").numbers = None
    gates = releases.gates(newest, {"3.0.0": old})
    assert gates.types["headlight"]["active"]["3.0.0"]["kind"] == "keyword"
    assert "numbers" not in gates.types["headlight"]["active"]["3.0.0"]
    assert releases.notes(gates)["headlight"]["active"] == (
        'MuJoCo 3.0.0: keyword false|true|auto, default "auto"')
    row = releases.type_row(releases.type_fields(newest, newest.elements["headlight"]
                                                 .attribute("active")))
    assert row.numbers == (("false", 0), ("true", 1), ("auto", 2))


def test_gates_list_the_children_only_older_releases_have() -> None:
    newest = ir.load()
    old = _older(newest, "3.0.0")
    old.elements["gone"] = copy.deepcopy(old.elements["site"])
    old.elements["gone"].name, old.elements["gone"].tag = "gone", "gone"
    old.elements["body"].children.append(ir.ChildDef("gone", "*", single=False))
    gates = releases.gates(newest, {"3.0.0": old})
    assert gates.removed == {"body": {"gone": ("3.0.0",)}}


def test_release_facts_replace_the_newest_s_entry_before_their_release(tmp_path: Path) -> None:
    facts = load_facts()
    path = tmp_path / "facts.toml"
    path.write_text('[[attribute]]\nuntil = "4.0.0"\nelement = "headlight"\nname = "active"\n'
                    'kind = "int"\ndefault = "1"\nreason = "MuJoCo 3 reads an int"\n',
                    encoding="utf-8")
    old = releases.release_facts(facts, "3.17.0", path)
    entries = [o for o in old.attributes if (o.element, o.name) == ("headlight", "active")]
    assert [(o.kind, o.default) for o in entries] == [("int", "1")]
    assert releases.release_facts(facts, "4.0.0", path) == facts
    path.write_text('[[attribute]]\nelement = "headlight"\nname = "active"\nreason = "x"\n',
                    encoding="utf-8")
    with pytest.raises(FactsError, match="until"):
        releases.release_facts(facts, "3.17.0", path)


def test_a_release_file_s_keywords_are_candidates_again() -> None:
    newest = ir.load()
    previous = _older(newest, "3.0.0")
    name = next(iter(previous.enums))
    previous.enums[name].values = [("older", "9"), *previous.enums[name].values]
    found = releases.with_keywords_of(newest, previous)
    assert found.enums[name].keywords == ["older", *newest.enums[name].keywords]
    assert "older" not in newest.enums[name].keywords  # a copy

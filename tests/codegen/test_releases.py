"""codegen/releases.py: what an older release's grammar lacks of the newest's, as the table
the runtime applies and as the attribute docs say it."""

from __future__ import annotations

import copy

from codegen import ir, releases, render


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

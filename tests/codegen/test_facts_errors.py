"""A mistake in ``schema/facts.toml`` ends ``python -m codegen generate`` in one line naming
the entry and what was expected, never in a traceback, and writes nothing."""

from __future__ import annotations

from pathlib import Path

import pytest

from codegen import __main__ as cli
from codegen import bindings, facts, ir, mujoco_stubs, render, wheel

TEXT = facts.FACTS_PATH.read_text(encoding="utf-8")
ATTRIBUTE = '\n[[attribute]]\nelement = "{row}"\nname = "{name}"\n{extra}reason = "x"\n'
CONSTRAINT = ('\n[[constraint]]\nelement = "{row}"\nkind = "exclusive"\n'
              'bundles = [["{a}"], ["b"]]\nreason = "x"\n')


def _edit(old: str, new: str) -> str:
    assert old in TEXT, old
    return TEXT.replace(old, new, 1)


MISTAKES: dict[str, tuple[str, str]] = {
    "attribute of no row": (
        TEXT + ATTRIBUTE.format(row="nosuchrow", name="type", extra=""),
        ("schema/facts.toml [[attribute]] nosuchrow@type: the synced schema has no such "
        "attribute; fix or remove the entry")),
    "attribute not on its row": (
        TEXT + ATTRIBUTE.format(row="geom", name="nosuch", extra=""),
        "schema/facts.toml [[attribute]] geom@nosuch: the synced schema has no such attribute"),
    "undeclared enum": (
        TEXT + ATTRIBUTE.format(row="geom", name="type", extra='enum = "nosuchenum"\n'),
        ("schema/facts.toml [[attribute]] geom@type: keyword attribute needs a declared enum, "
        "got 'nosuchenum'")),
    "kind without what it needs": (
        TEXT + ATTRIBUTE.format(row="geom", name="size", extra='kind = "ref"\n'),
        "schema/facts.toml [[attribute]] geom@size: ref attribute needs a namespace"),
    "wrong value type": (
        TEXT + ATTRIBUTE.format(row="geom", name="size", extra='required = "yes"\n'),
        (f"[[attribute]] #{TEXT.count(chr(10) + '[[attribute]]' + chr(10)) + 1} required: "
        "expected true or false, got 'yes'")),
    "constraint on no row": (
        TEXT + CONSTRAINT.format(row="nosuch", a="a"),
        "schema/facts.toml [[constraint]] nosuch: no row 'nosuch'"),
    "constraint on no attribute": (
        TEXT + CONSTRAINT.format(row="geom", a="sizes"),
        "schema/facts.toml [[constraint]] geom: row 'geom' has no attribute 'sizes'"),
    "language row": (
        _edit('joints = ["joint", "freejoint"]', 'joints = ["joint", "freejoints"]'),
        "schema/facts.toml [language] joints freejoints: no row 'freejoints'"),
    "language template": (
        _edit('replicate_copy = "{name}{sep}{index}"', 'replicate_copy = "{name}{s}{index}"'),
        ("schema/facts.toml [language]: replicate_copy: unknown placeholder {s} (known: "
        "index, name, sep)")),
    "language key missing": (
        _edit('mocap = "mocap"', ""), "[language]: missing key 'mocap' (a string)"),
    "language key misspelt": (
        _edit('mocap = "mocap"', 'mocapp = "mocap"'), "[language]: unknown key 'mocapp'"),
    "language value": (
        _edit('"option@timestep" = "min"', '"option@timestep" = "least"'),
        ("[language] merge_rules option@timestep: expected one of 'min', 'max', 'max-bytes', "
        "got 'least'")),
    "language attribute": (
        _edit('references = ["body", "frame"]', 'references = ["body", "frames"]'),
        "schema/facts.toml [language]: attach: <attach> has no attribute 'frames'"),
    "directory of no file": (
        _edit('"mesh@file" =', '"mesh@name" ='),
        "schema/facts.toml [directories] mesh@name: not a file attribute"),
    "class name of no row": (
        _edit('asset = "AssetSection"', 'assets = "AssetSection"'),
        "schema/facts.toml [class_names] assets: no row 'assets'"),
    "composition of no section": (
        _edit('statistic = "attributes"', 'statistics = "attributes"'),
        "schema/facts.toml [compose] statistics: no root section 'statistics'"),
    "attachment site of no row": (
        _edit('site = "dm_control attaches', 'sites = "dm_control attaches'),
        "schema/facts.toml [attachment_sites] sites: no row 'sites'"),
}


@pytest.fixture(scope="module")
def installed() -> wheel.Wheel:
    return wheel.read_wheel()


@pytest.fixture
def nothing_written(monkeypatch: pytest.MonkeyPatch, installed: wheel.Wheel) -> None:
    monkeypatch.setattr(wheel, "read_wheel", lambda: installed)  # read once per module

    def refuse(*args: object) -> None:
        raise AssertionError("the generator wrote despite the mistake")

    for module, name in ((ir, "dump"), (render, "write"), (bindings, "dump"),
                         (mujoco_stubs, "write")):
        monkeypatch.setattr(module, name, refuse)


@pytest.mark.parametrize("mistake", sorted(MISTAKES))
@pytest.mark.usefixtures("nothing_written")
def test_a_mistake_is_one_line(mistake: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                               capsys: pytest.CaptureFixture[str]) -> None:
    text, message = MISTAKES[mistake]
    path = tmp_path / "facts.toml"
    path.write_text(text, encoding="utf-8")
    monkeypatch.setattr(facts, "FACTS_PATH", path)
    assert cli.main(["generate"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("python -m codegen: error: "), err
    assert message in err, err


def test_the_repository_facts_are_accepted(monkeypatch: pytest.MonkeyPatch,
                                           nothing_written: None) -> None:
    """The mistakes above are mistakes: the unedited file gets as far as writing."""
    with pytest.raises(AssertionError, match="wrote despite"):
        cli.main(["generate"])

"""Facts about MJCF as a whole that differ between releases (schema/releases/behaviour.toml, the
generated table, ``typed_mjcf._releases.facts``): each checked against the installed MuJoCo
itself, and the behaviour of a release lacking it checked on any MuJoCo by applying that
release's facts (``apply(release)``), then the installed one's again."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support.compare import clear_asset_cache
from typed_mjcf._generated.release_facts import SINCE
from typed_mjcf._generated.releases import RELEASES
from typed_mjcf._releases import facts as _release_facts
from typed_mjcf._releases import gating as _releases
from typed_mjcf._releases.facts import ASSET_CACHE_CHECKS_CONTENTS, UNDERFLOWING_NUMBERS, has

TETRAHEDRON = "v 0 0 0\nv {s} 0 0\nv 0 {s} 0\nv 0 0 {s}\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
MESH_MODEL = ('<mujoco><asset><mesh name="m" file="m.obj"/></asset><worldbody><body>'
              '<geom type="mesh" mesh="m"/></body></worldbody></mujoco>')


def _without(fact: str) -> str:
    lacking = [r for r in RELEASES if not has(fact, r)]
    if not lacking:
        pytest.skip(f"every release covered has {fact}")
    return lacking[-1]


@pytest.fixture
def release() -> Iterator[None]:
    """A test may apply another release's facts: the installed one's are back after it."""
    yield
    _release_facts.apply()


def test_the_table_has_the_facts_the_runtime_applies() -> None:
    assert set(SINCE) == set(_release_facts.KNOWN)
    for fact, since in SINCE.items():  # from `since` on, every release has the fact
        assert [has(fact, r) for r in RELEASES] == [
            _releases.version_key(r) >= _releases.version_key(since) for r in RELEASES]
        assert has(fact, RELEASES[-1]), fact  # the newest has every fact


def _mujoco_reads(xml: str) -> bool:
    try:
        mujoco.MjSpec.from_string(xml)
    except ValueError as error:
        assert "number is too large" in str(error)
        return False
    return True


def test_underflowing_numbers_as_the_installed_mujoco_reads_them() -> None:
    """The fact, against the installed MuJoCo: it reads a subnormal exactly when the release
    in use has it, and so does typed-mjcf."""
    xml = '<mujoco><worldbody><geom size="1" friction="1 5e-324 1"/></worldbody></mujoco>'
    assert _mujoco_reads(xml) == has(UNDERFLOWING_NUMBERS)
    try:
        mjcf.from_xml_string(xml)
    except mjcf.ParseError as error:
        assert not has(UNDERFLOWING_NUMBERS)
        assert f"needs MuJoCo >= {SINCE[UNDERFLOWING_NUMBERS]}" in str(error)
    else:
        assert has(UNDERFLOWING_NUMBERS)


@pytest.mark.usefixtures("release")
def test_a_release_refusing_underflow_refuses_it_on_every_route() -> None:
    _release_facts.apply(_without(UNDERFLOWING_NUMBERS))
    since = f"needs MuJoCo >= {SINCE[UNDERFLOWING_NUMBERS]}"
    for xml in ('<mujoco><worldbody><geom size="1" friction="1 5e-324 1"/></worldbody></mujoco>',
                '<mujoco><worldbody><geom size="1" friction="1 1e-400 1"/></worldbody></mujoco>',
                '<mujoco><option timestep="1e-310"/></mujoco>',
                '<mujoco><worldbody><geom size="1" rgba="1e-40 0 0 1"/></worldbody></mujoco>'):
        with pytest.raises(mjcf.ParseError, match=since):
            mjcf.from_xml_string(xml)
    # what such a release reads: zero in any spelling, the smallest normal number, and 1e-40
    # where it is a double (only a float attribute underflows there)
    model = mjcf.from_xml_string(
        '<mujoco><option timestep="2.2250738585072014e-308"/><worldbody><geom size="1" '
        'friction="0e-400 -0 1e-40" rgba="0.0 1.1754944e-38 0 1"/></worldbody></mujoco>')
    geom = model.worldbody.geom[0]
    assert np.asarray(geom.friction).tolist() == [0.0, 0.0, 1e-40]
    assert model.option.timestep == 2.2250738585072014e-308
    # from Python: refused, naming the path, attribute, value and why; nothing changes
    with pytest.raises(mjcf.InvalidValueError, match=rf"worldbody/geom\[0\].*friction.*{since}"):
        geom.friction = (1, 5e-324, 1)
    assert np.asarray(geom.friction).tolist() == [0.0, 0.0, 1e-40]
    with pytest.raises(mjcf.InvalidValueError, match=since):
        geom.rgba = np.array([1e-40, 0, 0, 1])
    with pytest.raises(mjcf.InvalidValueError, match=since):
        model.option.timestep = 5e-324
    assert model.option.timestep == 2.2250738585072014e-308


@pytest.mark.usefixtures("release")
def test_the_newest_release_reads_underflowing_numbers_bit_for_bit() -> None:
    _release_facts.apply(RELEASES[-1])
    assert has(UNDERFLOWING_NUMBERS, RELEASES[-1])
    model = mjcf.from_xml_string(
        '<mujoco><worldbody><geom size="1" friction="1 5e-324 1e-400" rgba="1e-40 0 0 1"/>'
        '</worldbody></mujoco>')
    geom = model.worldbody.geom[0]
    assert np.asarray(geom.friction).tolist() == [1.0, 5e-324, 0.0]
    assert geom.rgba is not None and geom.rgba[0] == np.float32(1e-40)
    geom.friction = (1, -5e-324, 1)
    assert np.asarray(geom.friction).tolist() == [1.0, -5e-324, 1.0]


def _mesh_models(tmp_path: Path) -> list[mjcf.RootElement]:
    """Two models whose mesh file has one name, m.obj, and other contents (a tetrahedron,
    then one twice its size)."""
    models: list[mjcf.RootElement] = []
    for size in (1, 2):
        folder = tmp_path / str(size)
        folder.mkdir()
        (folder / "m.obj").write_text(TETRAHEDRON.format(s=size), encoding="utf-8")
        (folder / "model.xml").write_text(MESH_MODEL, encoding="utf-8")
        models.append(mjcf.from_path(folder / "model.xml"))
    return models


def test_models_sharing_a_file_name_compile_their_own_files(tmp_path: Path) -> None:
    """On the installed MuJoCo, whichever it is: compile() of the second model reads its own
    m.obj, not the first's (which MuJoCo < 4 serves from its cache by the name)."""
    first, second = (model.compile() for model in _mesh_models(tmp_path))
    assert np.allclose(second.geom_size[0], 2 * first.geom_size[0])


def test_the_asset_cache_fact_as_the_installed_mujoco_behaves() -> None:
    clear_asset_cache()
    small, large = (mujoco.MjModel.from_xml_string(
        MESH_MODEL, {"m.obj": TETRAHEDRON.format(s=s).encode()}) for s in (1, 2))
    reads_its_own = bool(np.allclose(large.geom_size[0], 2 * small.geom_size[0]))
    assert reads_its_own == has(ASSET_CACHE_CHECKS_CONTENTS)


@pytest.mark.usefixtures("release")
@pytest.mark.parametrize("clears", [False, True])
def test_compile_clears_the_asset_cache_for_a_release_serving_files_by_name(
        clears: bool) -> None:
    fact = ASSET_CACHE_CHECKS_CONTENTS
    _release_facts.apply(_without(fact) if clears else RELEASES[-1])
    cache = mujoco.mj_getCache()
    mujoco.MjModel.from_xml_string(MESH_MODEL, {"m.obj": TETRAHEDRON.format(s=1).encode()})
    assert mujoco.mj_getCacheSize(cache) > 0
    mjcf.RootElement().compile()  # a model without files
    assert (mujoco.mj_getCacheSize(cache) == 0) == clears

"""The two ways the text of ``to_xml_string()`` is loaded again, over every corpus model.

README "File names" is the contract: the text names every file as its source names it
(``<compiler meshdir>`` kept), and ``get_assets()`` keys each file by the base name of what the
text names, which is how MuJoCo's in-memory loader finds files. So, for every model of the
corpus (the MJCF files packaged with dm_control and mujoco, as ``test_corpus.py`` finds them)
that MuJoCo compiles by itself:

- in memory: ``MjModel.from_xml_string(m.to_xml_string(), m.get_assets())``, and
- beside the source: the text saved in the source's folder and loaded with
  ``MjModel.from_xml_path``

give the model MuJoCo compiles from the source, field by field (``test_corpus.py`` checks that
``m.compile()`` gives it too). The source's folder is a mirror of the packages (XML files
copied, every other file linked), so nothing is written into an installed package.
dm_control's ``model_with_assets.xml``, ``model_with_assetdir.xml`` and
``model_with_separators.xml`` name two files ``cube.stl`` in two folders (the same contents).
"""

from __future__ import annotations

import uuid
from pathlib import Path

import mujoco
import pytest

import typed_mjcf
from tests.support.compare import clear_asset_cache, model_differences
from tests.support.corpus import CORPUS, compiled, corpus_files, corpus_params, mirror

SHARED_NAMES = ("dm_control/mjcf/test_assets/model_with_assets.xml",
                "dm_control/mjcf/test_assets/model_with_assetdir.xml",
                "dm_control/mjcf/test_assets/model_with_separators.xml")


@pytest.fixture(autouse=True)
def _fresh_asset_cache() -> None:
    """Each test's compiles read their own files (tests/support/compare.py's clear_asset_cache)."""
    clear_asset_cache()


@pytest.fixture(scope="module")
def mirrored(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return mirror(tmp_path_factory.mktemp("corpus"))


def test_models_whose_files_share_a_name_are_in_the_corpus() -> None:
    idents = {ident for ident, _ in CORPUS}
    assert set(SHARED_NAMES) <= idents
    for ident, path in CORPUS:
        if ident in SHARED_NAMES:
            model = typed_mjcf.from_path(path)
            names = [str(m.file) for m in model.find_all("mesh")]
            assert "cube.stl" in names and "more_meshes/cube.stl" in names, ident


@pytest.mark.parametrize(("ident", "path"), corpus_params())
def test_text_loads_in_memory_and_beside_its_source(ident: str, path: Path,
                                                    mirrored: Path) -> None:
    expected = compiled(ident, path)
    model = typed_mjcf.from_path(path, files=corpus_files(ident, path))
    text = model.to_xml_string()
    assets = model.get_assets()
    in_memory = mujoco.MjModel.from_xml_string(text, assets)
    assert model_differences(expected, in_memory) == [], "in memory"
    beside = (mirrored / ident).with_name(f"{path.stem}.{uuid.uuid4().hex}.xml")
    beside.write_text(text, encoding="utf-8")
    try:
        saved = mujoco.MjModel.from_xml_path(str(beside))
    finally:
        beside.unlink()
    assert model_differences(expected, saved) == [], "saved beside its source"

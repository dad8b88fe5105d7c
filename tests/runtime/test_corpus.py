"""Round trip of every MJCF model shipped in the installed ``dm_control`` and ``mujoco`` packages.

The corpus is found at test time: every ``*.xml`` file in those packages whose root element is
``<mujoco>`` (dm_control's ``schema.xml`` and ``attribute_test_schema.xml`` are schemas, not
models, and so are not collected). Nothing is copied into this repository.

Two checks per file, each with the file's path (``package/relative/path.xml``) as its id:

``test_compiles_like_mujoco``
    For the files MuJoCo compiles by itself (``mujoco.MjModel.from_xml_path`` succeeds):
    ``typed_mjcf.from_path(path).compile()`` (which passes the files through MuJoCo's VFS)
    gives a model equal, field by field and bit for bit, to MuJoCo's own compile of the file.
    The other files are skipped with MuJoCo's error as the reason: they are pieces of larger
    models (include fragments, inputs of dm_control's model builders whose meshes live
    elsewhere) or deliberately broken test inputs, and have no compiled model to compare with.

``test_export_is_fixed_point``
    For the files MuJoCo parses by itself (``mujoco.MjSpec.from_file`` succeeds; it reads
    includes but not meshes or textures, and does not compile): exporting, parsing the export
    (relative to the original folder) and exporting again gives the same text. Files that
    MuJoCo cannot even parse (an ``<include>`` of a file that is not shipped), or that repeat
    a name (which 3.3.7's parser leaves to its compiler), are skipped with MuJoCo's error.

Files that legitimately cannot round trip are in ``XFAIL`` with the reason; the marks are
strict, so a file that starts passing must be taken off the list.
"""

from __future__ import annotations

from pathlib import Path
from typing import cast

import mujoco
import numpy as np
import pytest

import typed_mjcf
from tests.support.compare import Array, clear_asset_cache, file_differences, model_differences
from tests.support.corpus import (
    CORPUS,
    CORPUS_PACKAGES,
    OUTSIDE_FOLDER,
    XFAIL,
    compiled,
    corpus_files,
    skip_unless_mujoco_reads,
)


@pytest.fixture(autouse=True)
def _fresh_asset_cache() -> None:
    """Each test's compiles read their own files (tests/support/compare.py's clear_asset_cache)."""
    clear_asset_cache()


def _params() -> list[object]:
    params: list[object] = []
    for ident, path in CORPUS:
        marks: list[pytest.MarkDecorator] = []
        if ident in XFAIL:
            reason, raises = XFAIL[ident]
            marks.append(pytest.mark.xfail(reason=reason, raises=raises, strict=True))
        params.append(pytest.param(ident, path, id=ident, marks=marks))
    return params


def test_corpus_is_found() -> None:
    """Guard against silently testing nothing (the packages moved, the search broke)."""
    for package in CORPUS_PACKAGES:
        assert any(ident.startswith(package + "/") for ident, _ in CORPUS), package


@pytest.mark.parametrize(("ident", "path"), _params())
def test_compiles_like_mujoco(ident: str, path: Path) -> None:
    expected = compiled(ident, path)
    model = typed_mjcf.from_path(path, files=corpus_files(ident, path))
    actual = model.compile()
    assert model_differences(expected, actual) == []
    assert file_differences(expected, str(path), actual, model.get_assets()) == []


@pytest.mark.parametrize(("ident", "path"), _params())
def test_export_is_fixed_point(ident: str, path: Path) -> None:
    skip_unless_mujoco_reads(ident, path)
    xml = typed_mjcf.from_path(path).to_xml_string()
    again = typed_mjcf.from_xml_string(xml, base_dir=path.parent).to_xml_string()
    assert again == xml


@pytest.mark.parametrize(("ident", "path"), _params())
def test_only_the_listed_models_read_files_outside_their_folder(ident: str, path: Path) -> None:
    """By default a model reads files only inside its own folder: every corpus model that
    MuJoCo compiles reads all its files so, except those in OUTSIDE_FOLDER (refused without
    the folder they need, read with it)."""
    compiled(ident, path)
    model = typed_mjcf.from_path(path)
    if ident not in OUTSIDE_FOLDER:
        model.get_assets()  # a file outside the folder would be refused (FileAccessError)
        return
    with pytest.raises(typed_mjcf.FileAccessError, match="is outside the model's folder"):
        model.get_assets()
    allowed = typed_mjcf.from_path(path, files=corpus_files(ident, path))
    assert allowed.get_assets()


def test_comparison_sees_one_ulp() -> None:
    """The comparison is exact: a size one ulp off is a difference."""
    ident, path = next((i, p) for i, p in CORPUS if i == "dm_control/suite/cartpole.xml")
    expected = mujoco.MjModel.from_xml_path(str(path))
    model = typed_mjcf.from_path(path)
    geom = next(g for g in model.find_all("geom") if "size" in g.get_attributes())
    size = geom.get_attributes()["size"]
    assert isinstance(size, np.ndarray), ident
    geom.set_attributes(size=np.nextafter(cast(Array, size).astype(np.float64), np.inf))
    differences = model_differences(expected, model.compile())
    assert any(d.startswith("geom_size:") for d in differences), differences

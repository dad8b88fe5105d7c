"""validate() on every model of the corpus (the MJCF files shipped with dm_control and mujoco,
found at test time: ``tests/runtime/test_corpus.py``) and on the models of ``shapes.py``: no
error in a file MuJoCo's parser accepts, nor in what typed-mjcf writes for it, since
compile() refuses models with errors. (Compiling equal to MuJoCo and writing back unchanged
are checked in ``test_corpus.py`` and ``test_shapes.py``.)"""

from __future__ import annotations

from pathlib import Path

import pytest

import typed_mjcf
from tests.support.corpus import CORPUS, XFAIL, skip_unless_mujoco_reads
from typed_mjcf._model.validate import validate


def _errors(model: typed_mjcf.RootElement) -> list[str]:
    return [str(f) for f in validate(model) if f.severity == "error"]


@pytest.mark.parametrize(("ident", "path"), [pytest.param(i, p, id=i) for i, p in CORPUS
                                             if i not in XFAIL])
def test_no_error_in_models_mujoco_accepts(ident: str, path: Path) -> None:
    skip_unless_mujoco_reads(ident, path)
    model = typed_mjcf.from_path(path)
    assert _errors(model) == []
    written = typed_mjcf.from_xml_string(model.to_xml_string(), base_dir=path.parent)
    assert _errors(written) == []

"""validate() on every model of the corpus (the MJCF files shipped with dm_control and mujoco):
no error in a file MuJoCo's parser accepts, since compile() refuses models with errors."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

import typed_mjcf
from typed_mjcf._validate import validate

from ..runtime.test_corpus import CORPUS, XFAIL


@pytest.mark.parametrize(("ident", "path"), [pytest.param(i, p, id=i) for i, p in CORPUS
                                             if i not in XFAIL])
def test_no_error_in_models_mujoco_accepts(ident: str, path: Path) -> None:
    try:
        mujoco.MjSpec.from_file(str(path))
    except ValueError as error:
        pytest.skip(f"{ident}: MuJoCo does not parse it by itself: {' '.join(str(error).split())}")
    errors = [str(f) for f in validate(typed_mjcf.from_path(path)) if f.severity == "error"]
    assert errors == []

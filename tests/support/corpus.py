"""The corpus: every MJCF model packaged with dm_control and mujoco (found at test time,
nothing copied), MuJoCo's own compile and parse of each (made once per process and shared by
every corpus module), what each may read, and a writable mirror for commands that rewrite
files. ``tests/runtime/test_corpus.py`` checks the round trip over it."""

from __future__ import annotations

import functools
import importlib.util
import os
import re
import shutil
from pathlib import Path

import mujoco
import pytest
from lxml import etree

import typed_mjcf

CORPUS_PACKAGES = ("dm_control", "mujoco")

# Corpus files typed-mjcf cannot yet load or round-trip, with the reason (none today: names
# with '/', like model_with_separators.xml's "left/cube", load as written).
XFAIL: dict[str, tuple[str, type[Exception]]] = {}


def _root_tag(path: Path) -> str | None:
    try:
        for _, node in etree.iterparse(str(path), events=("start",), resolve_entities=False,
                                       no_network=True, load_dtd=False):
            return str(node.tag)
    except etree.XMLSyntaxError:
        return None
    return None


def corpus() -> list[tuple[str, Path]]:
    """``(id, path)`` of every MJCF model in the corpus packages, sorted by id."""
    found: list[tuple[str, Path]] = []
    for package in CORPUS_PACKAGES:
        spec = importlib.util.find_spec(package)
        if spec is None or spec.submodule_search_locations is None:
            continue
        for location in spec.submodule_search_locations:
            base = Path(location)
            for path in base.rglob("*.xml"):
                if _root_tag(path) == "mujoco":
                    found.append((f"{package}/{path.relative_to(base).as_posix()}", path))
    return sorted(found)


CORPUS = corpus()
# The corpus model whose names hold '/' (to-python writes no code that rebuilds it).
SEPARATORS = "dm_control/mjcf/test_assets/model_with_separators.xml"


@functools.cache
def _mujoco_compile(path: Path) -> mujoco.MjModel | str:
    try:
        return mujoco.MjModel.from_xml_path(str(path))
    except ValueError as error:
        return _one_line(error)


def compiled(ident: str, path: Path) -> mujoco.MjModel:
    """MuJoCo's own compile of a corpus file, made once per process (the corpus tests of
    every module compare against it and only read it); the test is skipped when MuJoCo
    refuses the file."""
    found = _mujoco_compile(path)
    if isinstance(found, str):
        pytest.skip(f"{ident}: MuJoCo does not compile it by itself: {found}")
    return found


# Corpus models that name files outside their own folder, which a model may read only when
# its loader allows it (typed_mjcf.FileAccess): the folder they need, from the model's.
OUTSIDE_FOLDER: dict[str, str] = {
    "dm_control/locomotion/walkers/assets/dog_v2/dog.xml": "../../../../suite/dog_assets",
}


def corpus_files(ident: str, path: Path) -> typed_mjcf.FileAccess | None:
    """What a corpus model may read: its folder, and the one it needs besides if listed."""
    extra = OUTSIDE_FOLDER.get(ident)
    return None if extra is None else typed_mjcf.FileAccess(roots=[path.parent / extra])


def _one_line(error: Exception) -> str:
    return " ".join(str(error).split())


@functools.cache
def _parser_checks_names() -> bool:
    """Whether the installed MuJoCo's parser refuses a repeated name (3.3.7's parses two
    bodies named alike and leaves the refusal to its compiler)."""
    try:
        mujoco.MjSpec.from_string(
            '<mujoco><worldbody><body name="a"/><body name="a"/></worldbody></mujoco>')
    except ValueError:
        return True
    return False


def skip_unless_mujoco_reads(ident: str, path: Path) -> None:
    """Skip the test unless MuJoCo reads ``path`` as a model: its parser accepts it (it reads
    includes, not meshes or textures) and no name repeats. A parser leaving names to the
    compiler (3.3.7) does not say the latter: there, a compile refusing a repeated name
    skips too (dog_v2/scene.xml repeats the texture "grid" of the dog.xml it includes)."""
    try:
        mujoco.MjSpec.from_file(str(path))
    except ValueError as error:
        pytest.skip(f"{ident}: MuJoCo does not parse it by itself: {_one_line(error)}")
    repeated = None if _parser_checks_names() else _repeated_name(path)
    if repeated is not None:
        pytest.skip(f"{ident}: MuJoCo refuses it when compiling: {repeated}")


@functools.cache
def _repeated_name(path: Path) -> str | None:
    """MuJoCo's compile error for ``path`` if it is about a repeated name."""
    try:
        mujoco.MjSpec.from_file(str(path)).compile()
    except ValueError as error:
        return _one_line(error) if "repeated name" in str(error) else None
    return None


def corpus_params() -> list[object]:
    return [pytest.param(ident, path, id=ident) for ident, path in CORPUS]


def module_name(ident: str) -> str:
    """A Python module file name for a corpus file (unique: the corpus path, flattened)."""
    return re.sub(r"\W", "_", ident.removesuffix(".xml")) + ".py"


def mirror(folder: Path) -> Path:
    """A copy of the corpus packages in ``folder``: the XML files copied (to be rewritten),
    every other file a link to the original. A corpus file ``ident`` is at ``folder/ident``."""
    for package in CORPUS_PACKAGES:
        spec = importlib.util.find_spec(package)
        assert spec is not None and spec.submodule_search_locations is not None
        base = Path(next(iter(spec.submodule_search_locations)))
        for here, _, files in os.walk(base):
            target = folder / package / Path(here).relative_to(base)
            target.mkdir(parents=True, exist_ok=True)
            for name in files:
                if name.endswith(".xml"):
                    shutil.copyfile(Path(here) / name, target / name)
                else:
                    (target / name).symlink_to(Path(here) / name)
    return folder

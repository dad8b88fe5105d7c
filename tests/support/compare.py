"""Field-by-field comparison of two compiled ``mujoco.MjModel`` objects.

Every public attribute of ``MjModel`` that is a numpy array, an int or bytes is compared
exactly (same shape and dtype; NaN equals NaN), and so is every field of the ``opt``, ``vis``
and ``stat`` structs. Names are compared as the strings ``name_*adr`` resolve to, besides the
raw ``names`` buffer.

File paths are the one deliberate exception: ``typed_mjcf`` compiles through MuJoCo's virtual
file system under flat file names, so ``paths``, ``npaths`` and the ``*_pathadr`` offsets
into it differ from a compile that read the files from disk. They are compared by meaning
instead (:func:`file_differences`): the same elements have a path, and each path names a file
with the same contents. What ``paths`` holds for a file read from disk differs by release:
the resolved path (model folder, ``meshdir`` or ``texturedir``, file; MuJoCo >= 3.17) or the
``file`` attribute as written (3.3.7); a relative one is resolved as MuJoCo resolved it. ``nbuffer`` includes the ``paths`` array, padded to MuJoCo's 64-byte
buffer alignment, so it is compared without that array.
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterator, Mapping
from typing import cast

import mujoco
import numpy as np

Array = np.ndarray[tuple[int, ...], np.dtype[np.generic]]

PATH_FIELDS = frozenset({"paths", "npaths", "nbuffer"})
BUFFER_ALIGNMENT = 64  # MuJoCo aligns every array of mjModel's buffer to 64 bytes


def clear_asset_cache() -> None:
    """Empty MuJoCo's asset cache, so that a test's compiles read their own files whatever
    the process compiled before: before 4.0.0 it serves a file by its name (another model's
    cube.stl) and 3.3.7 a mesh processed for another use (schema/releases/behaviour.toml)."""
    mujoco.mj_clearCache(mujoco.mj_getCache())


def _field(obj: object, name: str) -> object:
    value: object = getattr(obj, name)
    return value


def _int(obj: object, name: str) -> int:
    value = _field(obj, name)
    assert isinstance(value, int), name
    return value


def _bytes(obj: object, name: str) -> bytes:
    value = _field(obj, name)
    assert isinstance(value, bytes), name
    return value


def _is_path_field(name: str) -> bool:
    return name in PATH_FIELDS or name.endswith("_pathadr")


def _c_string(buffer: bytes, address: int) -> str:
    end = buffer.index(b"\0", address)
    return buffer[address:end].decode("utf-8", "replace")


def _addresses(model: mujoco.MjModel, name: str) -> list[int]:
    value = _field(model, name)
    assert isinstance(value, np.ndarray), name
    return [int(a) for a in cast(Array, value).ravel().tolist()]


def _struct_fields(prefix: str, struct: object) -> Iterator[tuple[str, object]]:
    """Leaf fields of MuJoCo's nested structs (``opt``, ``vis``, ``stat``)."""
    for name in dir(struct):
        if name.startswith("_"):
            continue
        value = _field(struct, name)
        if callable(value):
            continue
        if isinstance(value, np.ndarray | int | float | bytes | str):
            yield f"{prefix}.{name}", value
        else:
            yield from _struct_fields(f"{prefix}.{name}", value)


def model_fields(model: mujoco.MjModel) -> dict[str, object]:
    """Every comparable public field of a compiled model, by name."""
    fields: dict[str, object] = {}
    for name in dir(model):
        if name.startswith("_") or _is_path_field(name):
            continue
        value = _field(model, name)
        if isinstance(value, np.ndarray | int | float | bytes):
            fields[name] = value
        elif name in ("opt", "vis", "stat"):
            fields.update(_struct_fields(name, value))
    padded_paths = -(-_int(model, "npaths") // BUFFER_ALIGNMENT) * BUFFER_ALIGNMENT
    fields["nbuffer - padded npaths"] = _int(model, "nbuffer") - padded_paths
    names = _bytes(model, "names")
    for name in dir(model):
        if name.startswith("name_") and name.endswith("adr"):
            fields[f"{name} (resolved)"] = [_c_string(names, a) for a in _addresses(model, name)]
    return fields


def _as_arrays(a: object, b: object) -> tuple[Array, Array] | None:
    if isinstance(a, np.ndarray) and isinstance(b, np.ndarray):
        return cast(Array, a), cast(Array, b)
    return None


def _equal(a: object, b: object) -> bool:
    arrays = _as_arrays(a, b)
    if arrays is not None:
        left, right = arrays
        if left.shape != right.shape or left.dtype != right.dtype:
            return False
        return bool(np.array_equal(left, right, equal_nan=left.dtype.kind in "fc"))
    if isinstance(a, float) and isinstance(b, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    return type(a) is type(b) and a == b


def _describe(a: object, b: object) -> str:
    arrays = _as_arrays(a, b)
    if arrays is not None:
        return _describe_arrays(*arrays)
    text = f"{a!r} != {b!r}"
    return text if len(text) < 400 else text[:400] + "..."


def _describe_arrays(left: Array, right: Array) -> str:
    if left.shape != right.shape:
        return f"shape {left.shape} != {right.shape}"
    if left.dtype != right.dtype:
        return f"dtype {left.dtype} != {right.dtype}"
    same = left == right
    if left.dtype.kind in "fc":
        same |= np.isnan(left.astype(np.float64)) & np.isnan(right.astype(np.float64))
    differing = np.argwhere(~same)
    first = tuple(int(i) for i in differing[0])
    return (f"{len(differing)} entries differ, first at {first}: "
            f"{left[first]!r} != {right[first]!r}")


def model_differences(expected: mujoco.MjModel, actual: mujoco.MjModel) -> list[str]:
    """Human-readable differences between two compiled models (empty when equal)."""
    want, got = model_fields(expected), model_fields(actual)
    problems: list[str] = []
    for name in sorted(want.keys() | got.keys()):
        if name not in want or name not in got:
            problems.append(f"{name}: present in only one model")
        elif not _equal(want[name], got[name]):
            problems.append(f"{name}: {_describe(want[name], got[name])}")
    return problems


def _resolved_paths(model: mujoco.MjModel) -> dict[str, list[str | None]]:
    paths = _bytes(model, "paths")
    return {name: [None if a < 0 else _c_string(paths, a) for a in _addresses(model, name)]
            for name in dir(model) if name.endswith("_pathadr")}


# the compiler folder MuJoCo reads each kind's files from (assetdir already folded in)
_FOLDERS = {"mesh_pathadr": "meshdir", "hfield_pathadr": "meshdir", "skin_pathadr": "meshdir",
            "tex_pathadr": "texturedir"}


def _on_disk(model_path: str, field: str, stored: str) -> str:
    """The file ``stored`` (a path in ``paths``) names: absolute as most releases store it;
    relative, as 3.3.7 stores the ``file`` attribute, under the model's folder for its kind."""
    if os.path.isabs(stored):
        return stored
    spec = mujoco.MjSpec.from_file(model_path)  # the folders as MuJoCo read them (includes too)
    folder = _field(spec, _FOLDERS[field])
    assert isinstance(folder, str), field
    return os.path.join(os.path.dirname(model_path), folder, stored)


def file_differences(expected: mujoco.MjModel, expected_path: str, actual: mujoco.MjModel,
                     actual_files: Mapping[str, bytes]) -> list[str]:
    """Differences between the files two models were compiled from.

    ``expected`` read its files from disk (it was compiled from the file ``expected_path``);
    ``actual`` was compiled from the virtual file system ``actual_files``.
    """
    want, got = _resolved_paths(expected), _resolved_paths(actual)
    problems: list[str] = []
    for field in sorted(want.keys() | got.keys()):
        if len(want.get(field, [])) != len(got.get(field, [])):
            problems.append(f"{field}: {len(want.get(field, []))} != {len(got.get(field, []))}")
            continue
        for i, (a, b) in enumerate(zip(want[field], got[field], strict=True)):
            if a is None or b is None:
                if (a is None) != (b is None):
                    problems.append(f"{field}[{i}]: path {a!r} != {b!r}")
                continue
            with open(_on_disk(expected_path, field, a), "rb") as f:
                contents = f.read()
            if actual_files.get(b) != contents:
                problems.append(f"{field}[{i}]: {b!r} does not hold the contents of {a!r}")
    return problems

"""Field-by-field comparison of two compiled ``mujoco.MjModel`` objects.

Every public attribute of ``MjModel`` that is a numpy array, an int or bytes is compared
exactly (NaN equals NaN), and so is every field of the ``opt``, ``vis`` and ``stat`` structs.
Names are compared as the strings ``name_*adr`` resolve to, besides the raw ``names`` buffer.

File paths are the one deliberate exception: ``typed_mjcf`` compiles through MuJoCo's virtual
file system under flat file names, so ``paths``, ``npaths`` and the ``*_pathadr`` offsets
into it differ from a compile that read the files from disk. They are compared by meaning
instead: the same elements have a path, and each path names a file with the same contents.
``nbuffer`` includes the ``paths`` array, padded to MuJoCo's 64-byte buffer alignment, so it
is compared without that array.
"""

from __future__ import annotations

import os
from collections.abc import Iterator, Mapping

import mujoco
import numpy as np

PATH_FIELDS = frozenset({"paths", "npaths", "nbuffer"})
BUFFER_ALIGNMENT = 64  # MuJoCo aligns every array of mjModel's buffer to 64 bytes


def _is_path_field(name: str) -> bool:
    return name in PATH_FIELDS or name.endswith("_pathadr")


def _c_string(buffer: bytes, address: int) -> str:
    end = buffer.index(b"\0", address)
    return buffer[address:end].decode("utf-8", "replace")


def _struct_fields(prefix: str, struct: object) -> Iterator[tuple[str, object]]:
    """Leaf fields of MuJoCo's nested structs (``opt``, ``vis``, ``stat``)."""
    for name in dir(struct):
        if name.startswith("_"):
            continue
        value = getattr(struct, name)
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
        value = getattr(model, name)
        if isinstance(value, np.ndarray | int | float | bytes):
            fields[name] = value
        elif name in ("opt", "vis", "stat"):
            fields.update(_struct_fields(name, value))
    npaths: int = model.npaths
    padded_paths = -(-npaths // BUFFER_ALIGNMENT) * BUFFER_ALIGNMENT
    fields["nbuffer - padded npaths"] = model.nbuffer - padded_paths
    names: bytes = model.names
    for name in dir(model):
        if name.startswith("name_") and name.endswith("adr"):
            addresses = getattr(model, name)
            fields[f"{name} (resolved)"] = [_c_string(names, int(a)) for a in addresses]
    return fields


def _equal(a: object, b: object) -> bool:
    if isinstance(a, np.ndarray) and isinstance(b, np.ndarray):
        if a.shape != b.shape or a.dtype != b.dtype:
            return False
        equal_nan = a.dtype.kind in "fc"
        return bool(np.array_equal(a, b, equal_nan=equal_nan))
    if isinstance(a, float) and isinstance(b, float):
        return a == b or (a != a and b != b)
    return type(a) is type(b) and a == b


def _describe(a: object, b: object) -> str:
    if isinstance(a, np.ndarray) and isinstance(b, np.ndarray):
        if a.shape != b.shape:
            return f"shape {a.shape} != {b.shape}"
        if a.dtype != b.dtype:
            return f"dtype {a.dtype} != {b.dtype}"
        diff = np.argwhere(~((a == b) | (np.isnan(a) & np.isnan(b)) if a.dtype.kind in "fc"
                             else (a == b)))
        first = tuple(int(i) for i in diff[0])
        return (f"{len(diff)} entries differ, first at {first}: "
                f"{a[first]!r} != {b[first]!r}")
    text = f"{a!r} != {b!r}"
    return text if len(text) < 400 else text[:400] + "..."


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
    paths: bytes = model.paths
    resolved: dict[str, list[str | None]] = {}
    for name in dir(model):
        if name.endswith("_pathadr"):
            resolved[name] = [None if a < 0 else _c_string(paths, int(a))
                              for a in getattr(model, name)]
    return resolved


def file_differences(expected: mujoco.MjModel, expected_dir: str, actual: mujoco.MjModel,
                     actual_files: Mapping[str, bytes]) -> list[str]:
    """Differences between the files two models were compiled from.

    ``expected`` read its files from disk (relative paths are under ``expected_dir``);
    ``actual`` was compiled from the virtual file system ``actual_files``.
    """
    want, got = _resolved_paths(expected), _resolved_paths(actual)
    problems: list[str] = []
    for field in sorted(want):
        for i, (a, b) in enumerate(zip(want[field], got[field], strict=True)):
            if (a is None) != (b is None):
                problems.append(f"{field}[{i}]: path {a!r} != {b!r}")
                continue
            if a is None or b is None:
                continue
            with open(os.path.join(expected_dir, a), "rb") as f:
                contents = f.read()
            if actual_files.get(b) != contents:
                problems.append(f"{field}[{i}]: {b!r} does not hold the contents of {a!r}")
    return problems

"""Compiled ids by name for a whole kind of object at once, for a large ``bind``.

One ``mj_name2id`` call costs about as much as the rest of binding an element; reading a
kind's names out of ``MjModel.names`` in one pass is a tenth of that per object. MuJoCo
stores each object's name there followed by a NUL, kind after kind in id order; the table is
made only when the names are laid out so (checked against ``name_<kind>adr``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, cast

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    import mujoco


def name_ids(model: mujoco.MjModel, size: str) -> dict[str, int] | None:
    """Name -> compiled id of every named object of the kind counted by ``size``
    (``"njnt"``), the first of a repeated name as ``mj_name2id`` gives; ``None`` where the
    model does not lay the names out as expected (then ask ``mj_name2id``)."""
    count: object = getattr(model, size, None)
    found: object = getattr(model, f"name_{size[1:]}adr", None)
    if not isinstance(count, int) or count < 1 or not isinstance(found, np.ndarray):
        return None
    addresses = cast("npt.NDArray[np.int64]", found).astype(np.int64)  # int32 in MuJoCo
    text = cast(object, model.names)
    if not isinstance(text, bytes) or len(addresses) != count:
        return None
    start, last = int(addresses[0]), int(addresses[-1])
    end = text.find(b"\0", last)
    if not 0 <= start <= end:
        return None
    # each name ends where the next begins: its NUL just before the next address
    ends = np.flatnonzero(np.frombuffer(text, np.uint8, end - start, start) == 0) + start
    if not np.array_equal(ends, addresses[1:] - 1):
        return None
    try:
        names = text[start:end].decode("utf-8").split("\0")
    except UnicodeDecodeError:
        return None
    table = dict(zip(reversed(names), range(count - 1, -1, -1), strict=True))
    table.pop("", None)  # unnamed objects: no name finds them
    return table

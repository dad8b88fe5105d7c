"""Field documentation from ``mujoco.introspect``: the C header's comment and array extent.

``mujoco.introspect.structs`` describes every C struct field (``mjtNum* body_pos; //
position offset rel. to parent body (nbody x 3)``). The stubs get that text as the property's
docstring, so an editor shows what ``m.body_pos`` holds and its shape on hover. Types come from
pybind11's signatures, which give the dtype of every array; the shape is documentation only:
numpy's shape typing would turn every slice and arithmetic result into a different type.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from functools import cache


@dataclass(frozen=True)
class FieldDoc:
    """One C struct field: its comment and array extents (``("nbody", "3")``), if any."""

    doc: str
    extents: tuple[str, ...]

    def text(self) -> str:
        """The docstring: ``position offset rel. to parent body (nbody x 3)``."""
        if not self.extents:
            return self.doc
        return f"{self.doc} ({' x '.join(self.extents)})"


@cache
def struct_fields() -> dict[str, dict[str, FieldDoc]]:
    """``{C struct name: {field name: FieldDoc}}`` for every struct introspect knows."""
    # introspect is plain Python that the stubs do not cover; read it as data.
    structs = importlib.import_module("mujoco.introspect.structs")
    result: dict[str, dict[str, FieldDoc]] = {}
    for name, decl in structs.STRUCTS.items():
        fields: dict[str, FieldDoc] = {}
        for f in decl.fields:
            field_name = getattr(f, "name", None)
            if not isinstance(field_name, str):
                continue  # anonymous unions
            extent = getattr(f, "array_extent", None) or ()
            fields[field_name] = FieldDoc(str(getattr(f, "doc", "") or ""),
                                          tuple(str(e) for e in extent))
        result[str(name)] = fields
    return result


def _subsequence(short: str, long: str) -> bool:
    """``jnt`` in ``joint``, ``cam`` in ``camera``: the C prefixes abbreviate the view name."""
    remaining = iter(long)
    return all(ch in remaining for ch in short)


def _view_field(struct: dict[str, FieldDoc], group: str, name: str) -> FieldDoc | None:
    """The C field behind ``m.<group>(...).<name>``: ``body_pos``, ``jnt_qposadr``, ``xpos``."""
    if name in struct:
        return struct[name]
    candidates = [(prefix, doc) for field, doc in struct.items()
                  for prefix in (field.removesuffix("_" + name),)
                  if field.endswith("_" + name) and _subsequence(prefix, group.lower())]
    return candidates[0][1] if len(candidates) == 1 else None


def field_doc(class_name: str, field: str) -> str | None:
    """The docstring for property ``field`` of the Python class ``class_name``, if known.

    ``MjModel``/``MjvScene``/``MjsBody`` are the C structs ``mjModel``/``mjvScene``/``mjsBody``;
    ``_MjModelBodyViews`` (``m.body("x")``) shows the ``mjModel`` fields of one body.
    """
    every = struct_fields()
    if class_name.startswith("_Mj") and class_name.endswith("Views"):
        for owner in ("Model", "Data"):
            if class_name.startswith(f"_Mj{owner}"):
                group = class_name.removeprefix(f"_Mj{owner}").removesuffix("Views")
                found = _view_field(every.get(f"mj{owner}", {}), group, field)
                if found is None:
                    return None
                # a view holds one row: (nbody x 3) -> (3), (njnt) -> (1)
                return FieldDoc(found.doc, found.extents[1:] or ("1",)).text()
        return None
    if not class_name.startswith("Mj"):
        return None
    found = every.get("mj" + class_name[2:], {}).get(field)
    return None if found is None or not found.doc else found.text()


@cache
def _struct_decls() -> dict[str, object]:
    return dict(importlib.import_module("mujoco.introspect.structs").STRUCTS)


def element_struct(class_name: str, field: str) -> str | None:
    """The C struct an array or pointer field holds (``mjvScene.geoms`` -> ``mjvGeom``)."""
    if not class_name.startswith("Mj"):
        return None
    decl = _struct_decls().get("mj" + class_name[2:])
    for f in getattr(decl, "fields", ()):
        if getattr(f, "name", None) != field:
            continue
        inner = getattr(getattr(f, "type", None), "inner_type", None)
        name = getattr(inner, "name", None)
        if isinstance(name, str) and name.startswith("mj") and not name.startswith("mjt"):
            return name
    return None

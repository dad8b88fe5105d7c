"""The model test_export_signals.py exports, in a module of its own: the test's child
processes import it without pytest (a third of each child's start-up)."""

from __future__ import annotations

import typed_mjcf as mjcf

MESHES = 30  # and the model's XML: 31 renames


def model(version: str) -> mjcf.RootElement:
    root = mjcf.RootElement(model="m")
    root.option.timestep = 0.002 if version == "old" else 0.001  # the XML differs too
    for i in range(MESHES):
        root.asset.add_mesh(name=f"m{i}", file=mjcf.Asset(f"{version} {i}\n" * 100, ".obj",
                                                          f"m{i}"))
    return root

# Generated from src/typed_mjcf/_text/skin.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""MuJoCo's binary skin files (``.skn``) name the bodies their bones follow: in an attached
model those names take the model's scope, so its skin file is rewritten to match."""
from __future__ import annotations
NAME_BYTES = 40

def scope_bone_names(contents: bytes, prefix: str, where: str) -> bytes:
    """``contents`` with every bone's body name prefixed by ``prefix`` (``arm/``)."""
    ...

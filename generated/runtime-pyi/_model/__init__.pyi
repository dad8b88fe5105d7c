# Generated from src/typed_mjcf/_model/__init__.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Operations on a whole model: composition, defaults, validation, keyframes, limits, and
export with its checks (to a string, a folder or a zip)."""

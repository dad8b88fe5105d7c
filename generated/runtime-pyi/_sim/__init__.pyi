# Generated from src/typed_mjcf/_sim/__init__.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""MuJoCo itself: compiling, compiled names and ids, bindings, physics state and pictures."""

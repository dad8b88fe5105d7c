# Generated from src/typed_mjcf/_releases/__init__.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The installed MuJoCo's release: what its grammar lacks or types otherwise, and the
behaviour no grammar row states, applied to the core's tables when the grammar is loaded."""

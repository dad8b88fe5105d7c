# Generated from src/typed_mjcf/_text/__init__.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""XML in and out: parsing, export, and the files and assets a model names."""

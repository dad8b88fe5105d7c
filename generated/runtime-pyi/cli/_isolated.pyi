# Generated from src/typed_mjcf/cli/_isolated.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Compiling with MuJoCo in a child process, so that a crash inside MuJoCo (some malformed
models make it dereference a null pointer) is reported instead of killing the command.

The child reads the model's text and files (pickled by this module) on stdin and writes
MuJoCo's error, if any, on stdout; a child killed by a signal is a crash.
"""
from __future__ import annotations
from collections.abc import Mapping
from typed_mjcf.errors import CompileError

class MujocoCrashed(CompileError):
    """MuJoCo's compiler died (a signal, or an exit without an answer) on the model."""

def compile_in_child(xml: str, files: Mapping[str, bytes]) -> str | None:
    """MuJoCo's error compiling ``xml`` with ``files``, or ``None`` if it compiled; raises
    :class:`MujocoCrashed` if the compiler crashed."""
    ...

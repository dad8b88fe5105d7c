# Generated from src/typed_mjcf/cli/to_python.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``typed-mjcf to-python``: typed-mjcf code that rebuilds an MJCF model.

The code is one function per file: ``build()`` for the model file, returning the
``RootElement``, and an ``add_<name>(parent)`` for each ``<include>``d file, called where the
file was included. Elements are added with ``add_<tag>()`` calls in the order MuJoCo reads
them, their attributes as keyword arguments in MJCF's order; an element gets a variable only
when later code uses it (to add its children, or where a reference names it), and references
to elements made earlier in the same function are passed as those variables (so type
checkers check them too); the others are passed by name. Once-only sections without
attributes are reached through their properties (``model.worldbody``).

Numbers are written as the file spells them, the way a person would type them (``0.1``,
``2e-6``, ``(0, 0, 1)``), except where Python's double would not round to the same ``float``
MuJoCo reads. File paths are written as the file writes them; the model is built with
``model_dir=str(MODEL_DIR)``, the model file's folder relative to the module's (``HERE``), so
they (and ``meshdir`` and the like) mean what they meant in the file.
"""
from __future__ import annotations
import argparse
from typed_mjcf.tooling import (
    ArrayCodec,
    AttributeSpec,
    Element,
    KeywordCodec,
    ModelBase,
    grammar_facts,
    iter_written,
    make_codec,
    to_float,
)
NAME = "to-python"
HELP = "write typed-mjcf Python code that rebuilds a model"
DESCRIPTION = """\
Write Python that rebuilds MODEL.xml with typed-mjcf: a function build() returning the
model (mjcf.RootElement), add_<tag>() calls with keyword arguments in MJCF's attribute order,
variables for the elements later code uses (references to them are passed as variables, so
mypy and pyright check them), default classes as add_default() blocks, and each <include>d
file as a function of its own. Values are written as a person would type them (0.1, not
0.10000000149011612; tuples for arrays). The code is formatted (lines of at most 100
characters) and passes mypy --strict and pyright's strict mode; running it prints the model.

Paths of the files the model uses (meshes, textures, ...) are written as the model writes
them (file="arm.stl" under meshdir="meshes" stays so), and the model is built with
model_dir=str(MODEL_DIR), MODEL_DIR being the model's folder relative to the output file's
folder (without -o, the current folder): exported again, the model names its files as the
original did.

A model whose element names hold "/" cannot be written: typed-mjcf's Python API keeps "/"
for the names of attached models.

exit status: 0 written, 2 the model cannot be read (or written as Python)."""

def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    ...

def run(args: argparse.Namespace) -> int: ...

def to_python(model: ModelBase, folder: str) -> str:
    """The code of a module that rebuilds ``model`` (read from a file); its files are found
    relative to ``folder``, where the module will be. Raises :class:`BadInput` for a model
    typed-mjcf's Python API cannot build."""
    ...

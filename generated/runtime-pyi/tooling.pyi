# Generated from src/typed_mjcf/tooling.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The internal API for tools built on typed-mjcf, its own command line first.

Stable within a minor release (``0.1.x``), not the user API: user code imports
``typed_mjcf`` (and ``typed_mjcf.io``, ``typed_mjcf.errors``, ...). The command line
imports only those and this module; what it needs of the runtime is named here once, so a
change inside the runtime's folders shows here and nowhere else.

- the tree: the base element class, the root's, and functions reading an element's slots
  (its children, stored values, name, scope, model, where it was read from);
- the grammar: rows and attributes (``ElementSpec``, ``AttributeSpec``), the
  language facts, the generated class of a row;
- values: the codecs' export format, their refusal, the two codec kinds the code writer
  spells, one codec per attribute signature, and the one spelling of reals;
- reading: a parse that collects problems instead of stopping, with source lines;
- writing: the elements an export writes, the text MuJoCo compiles, XML escaping;
- defaults, limits and previews: resolving every attribute, compile and render bounds,
  pictures of one model or two;
- versions: the MuJoCo release the tables describe, and those the runtime covers.
"""
from __future__ import annotations
from typed_mjcf._build import describe as describe_build
from typed_mjcf._core.access import DEFAULT_ACCESS
from typed_mjcf._core.codecs import (
    ArrayCodec,
    Format,
    KeywordCodec,
    Rejected,
    make_codec,
    real_text,
    to_float,
)
from typed_mjcf._core.grammar import AttributeSpec, ElementSpec
from typed_mjcf._core.sourcelines import start_line
from typed_mjcf._core.tree import (
    Element,
    ModelBase,
    children,
    element_class,
    element_name,
    grammar_facts,
    model_of,
    read_value,
    reference_namespace,
    scope_of,
    source_map,
    source_of,
    values,
)
from typed_mjcf._generated import MUJOCO_VERSION
from typed_mjcf._model.defaults import resolve_all
from typed_mjcf._model.resource_limits import (
    DEFAULT_COMPILE_LIMITS,
    DEFAULT_RENDER_LIMITS,
    check_compile,
)
from typed_mjcf._releases.gating import describe as describe_releases
from typed_mjcf._sim.preview import key_from_text, render, render_pair, write_png
from typed_mjcf._sim.text import vfs_text
from typed_mjcf._sim.warp_refusals import Refusal, WarpMissingError, warp_modules, warp_refusals
from typed_mjcf._text.export import iter_written, written_children
from typed_mjcf._text.parse import INCLUDE, ParseOptions, Problem, parse_path, root_class
from typed_mjcf._text.xmltext import MAX_INDENT, escape
__all__ = [
    "DEFAULT_ACCESS",
    "DEFAULT_COMPILE_LIMITS",
    "DEFAULT_RENDER_LIMITS",
    "INCLUDE",
    "MAX_INDENT",
    "MUJOCO_VERSION",
    "ArrayCodec",
    "AttributeSpec",
    "Element",
    "ElementSpec",
    "Format",
    "KeywordCodec",
    "ModelBase",
    "ParseOptions",
    "Problem",
    "Refusal",
    "Rejected",
    "WarpMissingError",
    "check_compile",
    "children",
    "describe_build",
    "describe_releases",
    "element_class",
    "element_name",
    "escape",
    "grammar_facts",
    "iter_written",
    "key_from_text",
    "make_codec",
    "model_of",
    "parse_path",
    "read_value",
    "real_text",
    "reference_namespace",
    "render",
    "render_pair",
    "resolve_all",
    "root_class",
    "scope_of",
    "source_map",
    "source_of",
    "start_line",
    "to_float",
    "values",
    "vfs_text",
    "warp_modules",
    "warp_refusals",
    "write_png",
    "written_children",
]

# Generated from src/typed_mjcf/_sim/text.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""A model's text with what writing it needs resolved first: its files collected (the
``<asset><model>`` files among them parsed) and, for a composed model whose keyframes are
combined, the layout MuJoCo compiles; then :mod:`typed_mjcf._model.write` only writes."""
from __future__ import annotations
from collections.abc import Callable
from typed_mjcf._core.codecs import DEFAULT_FORMAT, Format
from typed_mjcf._core.names import NameScope
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._model.resource_limits import DEFAULT_COMPILE_LIMITS, CompileLimits, check_compile
from typed_mjcf._text.export import Writer
from typed_mjcf._text.files import CollectedFiles
import mujoco

def model_text(element: Element, fmt: Format = DEFAULT_FORMAT, pretty_print: bool = True,
               collected: CollectedFiles | None = None, names_from: NameScope | None = None,
               self_only: bool = False, namer: Callable[[Writer], None] | None = None,
               limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> str:
    """:func:`~typed_mjcf._model.write.element_text` of ``element`` (the same arguments),
    its files and keyframe layout resolved first; ``limits`` bound the layout's compile."""
    ...

def vfs_text(model: ModelBase, fmt: Format = DEFAULT_FORMAT, pretty_print: bool = True,
             namer: Callable[[Writer], None] | None = None,
             limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> tuple[str, CollectedFiles]:
    """The model's XML with every file by its flat name (and no folder attributes), and the
    files: what MuJoCo compiles from memory and what a folder export writes (``namer``,
    ``limits``: as for :func:`model_text`)."""
    ...

def keyframe_layout(model: ModelBase, fmt: Format, pretty_print: bool,
                    collected: CollectedFiles | None, names_from: NameScope | None,
                    limits: CompileLimits) -> mujoco.MjModel:
    """The composed model compiled without keyframes: where each part's values go."""
    ...

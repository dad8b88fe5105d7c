"""A model's text with what writing it needs resolved first: its files collected (the
``<asset><model>`` files among them parsed) and, for a composed model whose keyframes are
combined, the layout MuJoCo compiles; then :mod:`typed_mjcf._model.write` only writes."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from typed_mjcf._core.codecs import DEFAULT_FORMAT, Format
from typed_mjcf._core.names import NameScope
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._model.keyframes import LayoutError
from typed_mjcf._model.resource_limits import DEFAULT_COMPILE_LIMITS, CompileLimits, check_compile
from typed_mjcf._model.validate import ensure_no_crash
from typed_mjcf._model.write import (
    collect,
    element_text,
    files_to_collect,
    keyless_text,
    needs_layout,
)
from typed_mjcf._sim.compile import compile_from_memory
from typed_mjcf._text.export import Writer
from typed_mjcf._text.files import CollectedFiles

if TYPE_CHECKING:
    import mujoco


def model_text(element: Element, fmt: Format = DEFAULT_FORMAT, pretty_print: bool = True,
               collected: CollectedFiles | None = None, names_from: NameScope | None = None,
               self_only: bool = False, namer: Callable[[Writer], None] | None = None,
               limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> str:
    """:func:`~typed_mjcf._model.write.element_text` of ``element`` (the same arguments),
    its files and keyframe layout resolved first; ``limits`` bound the layout's compile."""
    collected = files_to_collect(element, collected, self_only)
    layout = None
    if needs_layout(element, self_only):
        assert isinstance(element, ModelBase)
        layout = keyframe_layout(element, fmt, pretty_print, collected, names_from, limits)
    return element_text(element, fmt, pretty_print, collected, names_from, self_only, namer,
                        layout)


def vfs_text(model: ModelBase, fmt: Format = DEFAULT_FORMAT, pretty_print: bool = True,
             namer: Callable[[Writer], None] | None = None,
             limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> tuple[str, CollectedFiles]:
    """The model's XML with every file by its flat name (and no folder attributes), and the
    files: what MuJoCo compiles from memory and what a folder export writes (``namer``,
    ``limits``: as for :func:`model_text`)."""
    collected = collect(model)
    return model_text(model, fmt, pretty_print, collected, namer=namer,
                      limits=limits), collected


def keyframe_layout(model: ModelBase, fmt: Format, pretty_print: bool,
                    collected: CollectedFiles | None, names_from: NameScope | None,
                    limits: CompileLimits) -> mujoco.MjModel:
    """The composed model compiled without keyframes: where each part's values go."""
    # the text's own refusals first, then what would crash MuJoCo or pass the limits
    text = keyless_text(model, fmt, pretty_print, collected, names_from)
    ensure_no_crash(model)
    check_compile(model, limits)
    if collected is None:  # the layout is compiled from memory: files by flat names
        collected = collect(model)
        text = keyless_text(model, DEFAULT_FORMAT, False, collected)
    try:
        return compile_from_memory(text, collected.files)
    except ValueError as error:
        raise LayoutError(str(error)) from None

"""``dm_control.mjcf.debugging``: debug mode, which records where each element was made
and each attribute last set (``element.get_init_stack()``,
``element.get_last_modified_stacks_for_all_attributes()``), and says so when MuJoCo (or
``validate()`` before it) refuses a model given to ``mjcf.Physics``.

Debug mode is on by ``--pymjcf_debug`` (absl flags, defined by
``install_as_dm_control_mjcf()`` when absl is installed, as dm_control defines them, and read
when the first element is made) or :func:`enable_debug_mode`. With
``--pymjcf_debug_full_dump_dir`` (or :func:`set_full_dump_dir`), a refused model is written
there as ``model.xml``, every element's line ending in ``<!--pymjcfdebug:<id>-->``, with
``<id>.dump`` telling where that element was made and each attribute set.
"""

from __future__ import annotations

import contextlib
import copy
import importlib
import os
import re
from collections.abc import Generator, Iterator
from typing import Final, NamedTuple, cast

from lxml import etree

from typed_mjcf._base import Element, ModelRoot
from typed_mjcf._core import debuginfo as _debuginfo
from typed_mjcf._core import tree as _tree
from typed_mjcf._core.debuginfo import StackTraceEntry
from typed_mjcf._core.errors import CompileError
from typed_mjcf._model.validate import ValidationError
from typed_mjcf._model.write import collect
from typed_mjcf._sim.locate import written_nodes
from typed_mjcf.types import XmlElement

DEBUG_METADATA_PREFIX: Final = "pymjcfdebug"
_DEBUG_FLAG: Final = "pymjcf_debug"
_DUMP_FLAG: Final = "pymjcf_debug_full_dump_dir"
_SEPARATOR: Final = "\n" + "=" * 80 + "\n"
_MARK_ON_NEXT_LINE: Final = re.compile(r"\n\s*<!--" + DEBUG_METADATA_PREFIX)
# [debug mode, dump folder]: None until set, or read from the flags when first asked
_MODE: Final[list[bool | None]] = [None]
_DUMP_DIR: Final[list[str | None]] = [None]
_FLAGS: Final[list[object]] = []  # absl's FLAGS, once the flags are defined


class ElementDebugInfo(NamedTuple):
    element: object
    init_stack: list[StackTraceEntry]
    attribute_stacks: dict[str, list[StackTraceEntry]]


def _define_flags() -> None:
    """Define dm_control's two flags in absl's ``FLAGS``, if absl is installed (a dependency
    of dm_control, not of typed-mjcf) and they are not defined yet. They may be overridden:
    dm_control's own debugging module, imported in the same process, defines them again."""
    if _FLAGS:
        return
    try:
        flags = importlib.import_module("absl.flags")
    except ImportError:
        return
    values: object = flags.FLAGS
    defined = getattr(values, "__contains__")  # noqa: B009 - absl's FlagValues, untyped here
    if not defined(_DEBUG_FLAG):
        flags.DEFINE_boolean(
            _DEBUG_FLAG, False, "Enables PyMJCF debug mode (SLOW!): where each element of "
            "an MJCF model was made and each attribute set is recorded, and said when "
            "MuJoCo refuses the model (typed-mjcf's dm_control.mjcf).", allow_override=True)
    if not defined(_DUMP_FLAG):
        flags.DEFINE_string(_DUMP_FLAG, "", "Path to dump full debug info when MuJoCo "
                            "refuses a model (typed-mjcf's dm_control.mjcf).",
                            allow_override=True)
    _FLAGS.append(values)


def _flag(name: str) -> object:
    """A flag's value: the command line's once absl parsed it, its default before."""
    if not _FLAGS:
        return None
    # absl's Flag: its value is the default until the command line is parsed
    return getattr(getattr(_FLAGS[0], "__getitem__")(name), "value")  # noqa: B009 - untyped


def debug_mode() -> bool:
    """Whether debug mode is on (first asked: ``--pymjcf_debug``)."""
    mode = _MODE[0]
    if mode is None:
        mode = bool(_flag(_DEBUG_FLAG))
        _set_mode(mode)
    return mode


def enable_debug_mode() -> None:
    _set_mode(True)


def disable_debug_mode() -> None:
    _set_mode(False)


def _set_mode(on: bool) -> None:
    _MODE[0] = on
    _debuginfo.set_recording(on)


def _resolve_then_record(element: object, names: tuple[str, ...] | None,
                         creating: bool) -> None:
    """The recorder until debug mode is known: reads the flags, as dm_control does when
    the first element is made, then records as they say."""
    debug_mode()
    recorder = _debuginfo.RECORDER[0]
    if recorder is not None:
        recorder(element, names, creating)


def arm() -> None:
    """Define dm_control's flags and read ``--pymjcf_debug`` when the first element is made
    (``install()`` calls it: absl parses the command line after the imports, in
    ``app.run``)."""
    _define_flags()
    if _MODE[0] is None:
        _debuginfo.RECORDER[0] = _resolve_then_record


def get_full_dump_dir() -> str:
    """Where a refused model's full debug information is written (``''``: nowhere)."""
    folder = _DUMP_DIR[0]
    if folder is None:
        folder = str(_flag(_DUMP_FLAG) or "")
        _DUMP_DIR[0] = folder
    return folder


def set_full_dump_dir(dump_path: str) -> None:
    _DUMP_DIR[0] = dump_path


def get_current_stack_trace() -> list[StackTraceEntry]:
    """The stack of the calling code, up to where it entered typed-mjcf."""
    return _debuginfo.current_stack()


@contextlib.contextmanager
def freeze_current_stack_trace() -> Generator[None]:
    """While the block runs, what is made or set is recorded with the stack of its start."""
    if not debug_mode():
        yield
        return
    before = _debuginfo.freeze(_debuginfo.current_stack())
    try:
        yield
    finally:
        _debuginfo.freeze(before)


# ---------------------------------------------------------------------------- errors


def explained(error: ValueError, model: ModelRoot) -> ValueError:
    """``error`` (refusing ``model`` for a physics) with dm_control's advice appended: out
    of debug mode, how to turn it on; in it, where each element the error names was made
    and its attributes set (and the full dump written, when a folder is set)."""
    if not debug_mode():
        note = ("run again with --pymjcf_debug (dm_control's debug mode) for where the "
                "element named was made and its attributes set")
    else:
        folder = get_full_dump_dir()
        if folder:
            dump_full_debug_info(model, folder)
        lines = [_summary(element, folder) for element in _named_elements(error, model)]
        note = "\n".join(lines) or "(debug mode: the error names no element of the model)"
    error.args = (f"{error}\n{note}",)  # the same error, its findings or path kept
    return error


def _named_elements(error: ValueError, model: ModelRoot) -> list[Element]:
    """The elements ``error`` is about."""
    found: list[object] = []
    if isinstance(error, ValidationError):
        found += [f.element for f in error.errors]
    elif isinstance(error, CompileError) and error.path is not None:
        found += [e for e in _tree.iter_composed(model, True) if e.path == error.path][:1]
    return [e for e in dict.fromkeys(found) if isinstance(e, Element)]


def _where(entry: StackTraceEntry) -> str:
    return f"`{entry.function_name}` at {entry.filename}:{entry.line_number}"


def _summary(element: Element, folder: str) -> str:
    """dm_control's "Debug summary for element" lines."""
    out = [f"Debug summary for element {element.path}:"]
    if not folder:
        out.append(f"  * Full debug info can be dumped to disk by setting the flag "
                   f"--{_DUMP_FLAG}=path/to/dump")
    init = element.get_init_stack()
    out.append(f"  * Element object was created by {_where(init[-1])}" if init else
               "  * Element object was made before debug mode was on")
    for name, value, stack, at_creation in _changes(element, init):
        if at_creation:
            out.append(f'  * {name}="{value}" was set when the element was created')
        elif value is not None:
            out.append(f'  * {name}="{value}" was set by {_where(stack[-1])}')
        else:
            out.append(f"  * {name} was CLEARED by {_where(stack[-1])}")
    return "\n".join(out)


def _changes(element: Element, init: list[StackTraceEntry],
             ) -> Iterator[tuple[str, str | None, list[StackTraceEntry], bool]]:
    """Each attribute with a recorded change: name, value (None: cleared), the stack of its
    last change, and whether that was the element's creation (reported only when set)."""
    for name, stack in element.get_last_modified_stacks_for_all_attributes().items():
        value = element.get_attribute_xml_string(name)
        if not stack:
            continue
        at_creation = bool(init) and stack[-1] == init[-1]
        if at_creation and value is None:
            continue
        yield name, value, stack, at_creation


def dump_full_debug_info(model: ModelRoot, dump_dir: str) -> None:
    """Write ``model.xml`` (each element's lines ending in ``<!--pymjcfdebug:<id>-->``) and
    one ``<id>.dump`` per element into ``dump_dir``, as dm_control's debug mode does."""
    root, pairs = written_nodes(model, collect(model))
    for node in root.iter():  # indented again below, with the marks
        if node.text is not None and not node.text.strip():
            node.text = None
        node.tail = None
    for node, element in pairs:
        if not isinstance(element, Element):
            continue
        mark = f"{DEBUG_METADATA_PREFIX}:{id(element)}"
        with open(os.path.join(dump_dir, f"{id(element)}.dump"), "w", encoding="utf-8") as f:
            f.write(f"{mark}\n{_self_only(node)}\n")
            _dump_stacks(f, element)
        if len(node):
            node.insert(0, etree.Comment(mark))
        node.addnext(etree.Comment(mark))
    text = etree.tostring(root, pretty_print=True, encoding="unicode")
    # each mark on the line of the tag it follows, as dm_control writes it
    text = _MARK_ON_NEXT_LINE.sub("<!--" + DEBUG_METADATA_PREFIX, text)
    with open(os.path.join(dump_dir, "model.xml"), "w", encoding="utf-8") as f:
        f.write(text)


def _self_only(node: XmlElement) -> str:
    """The node's own tag, its children as ``...`` (as ``str(element)`` writes it)."""
    shallow = copy.copy(node)
    shallow.tail = None
    if len(shallow):
        for child in list(shallow):
            shallow.remove(child)
        shallow.text = "..."
    return etree.tostring(shallow, encoding="unicode")


def _dump_stacks(f: object, element: Element) -> None:
    write = getattr(f, "write")  # noqa: B009 - a text file

    def stack_lines(header: str, stack: list[StackTraceEntry]) -> None:
        write(header + "\n")
        for entry in stack:
            write(f"    `{entry.function_name}` at {entry.filename}:{entry.line_number}\n"
                  f"        {entry.text}\n")
        write(_SEPARATOR)

    init = element.get_init_stack()
    stack_lines("Element creation", init)
    for name, value, stack, at_creation in _changes(element, init):
        if at_creation:
            write(f'Attribute {name}="{value}"\n    was set when the element was created'
                  f"{_SEPARATOR}")
        elif value is not None:
            stack_lines(f'Attribute {name}="{value}"', stack)
        else:
            stack_lines(f"Attribute {name} was CLEARED", stack)


__all__ = ["DEBUG_METADATA_PREFIX", "ElementDebugInfo", "StackTraceEntry", "debug_mode",
           "disable_debug_mode", "dump_full_debug_info", "enable_debug_mode",
           "freeze_current_stack_trace", "get_current_stack_trace", "get_full_dump_dir",
           "set_full_dump_dir"]


def _explained(error: ValueError, model: _tree.ModelBase) -> ValueError:
    """:func:`explained`, lent to ``Physics`` (``compile_error_advice``) through the tree."""
    if not isinstance(model, ModelRoot):
        return error
    # (its camera and key types play no part here)
    return explained(error, cast("ModelRoot[_tree.Element, _tree.Element]", model))


def _lend() -> None:
    _tree.COMPAT.explained = _explained


_lend()

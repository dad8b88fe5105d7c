"""Compiling a model for a physics, and which compiled objects each element became.

A named element is found by the name it is written with (its scope's prefix and its name):
``mj_name2id``. An unnamed one has no name to find it by, and MuJoCo's order of objects is not
the document's (a body's geoms come before its children's, replicates copy, ``<attach>``
reads other files), so the model is written with a marker name on every unnamed element that
can be bound, read into an ``MjSpec``, the markers found there (a ``<replicate>``'s copies
carry the marker with their suffix), set back to no name, and the spec compiled: the objects
keep the ids the compiler gives them, and the model is the one the text without markers
gives (names do not change how MuJoCo compiles).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Final, cast

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.errors import CompileError
from typed_mjcf._core.grammar import ElementSpec
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
from typed_mjcf._model.resource_limits import DEFAULT_COMPILE_LIMITS, CompileLimits, check_compile
from typed_mjcf._model.validate import ensure_valid
from typed_mjcf._sim.binding import binding_tables
from typed_mjcf._sim.bridge import compile_model
from typed_mjcf._sim.compile import compile_from_memory
from typed_mjcf._sim.text import model_text, vfs_text
from typed_mjcf._text.export import Writer
from typed_mjcf._text.files import element_file_stem

if TYPE_CHECKING:
    import mujoco

_MARK: Final = "typed-mjcf-bind-"  # marker names: no model names its elements so
_MARKED: Final = re.compile(re.escape(_MARK) + r"(\d+)-")
_UNMARK: Final = re.compile(r' [A-Za-z_]+="[^"]*' + re.escape(_MARK) + r'\d+-"')


def kind_of(element: Element) -> str | None:
    """The kind of compiled object ``element`` becomes (``"joint"``, ``"body"`` for the world
    body too), or ``None`` if it becomes none MuJoCo indexes."""
    spec = element.spec
    namespace = spec.namespace
    if namespace is None and spec.holds_bodies and isinstance(element.parent, ModelBase):
        namespace = grammar_facts().body  # the world body is body 0
    return bound_kind(namespace)


def bound_kind(namespace: str | None) -> str | None:
    """``namespace`` if its elements become objects MuJoCo indexes (a kind bind knows)."""
    return namespace if namespace in binding_tables().kinds else None


def row_kind(cls: type) -> str | None:
    """The kind of every element of class ``cls``: its row's namespace, if MuJoCo binds it
    (``None`` for the world body's row, which has none: :func:`kind_of` decides it)."""
    spec = getattr(cls, "spec", None) if issubclass(cls, Element) else None
    return bound_kind(spec.namespace) if isinstance(spec, ElementSpec) else None


@dataclass(frozen=True, slots=True)
class Compiled:
    """A compiled model, and the compiled ids of the elements bound without their own name
    (``id(element) -> (element, ids)``; a replicated element has one id per copy)."""

    model: mujoco.MjModel
    unnamed: Mapping[int, tuple[Element, tuple[int, ...]]]


def compile_for_physics(model: ModelBase,
                        limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> Compiled:
    """Validate and compile ``model`` as ``compile()`` does (within ``limits``), keeping the
    ids of its unnamed elements (and of those the export names, as it names attachment
    frames)."""
    ensure_valid(model)
    check_compile(model, limits)
    marks: list[Element] = []
    written: dict[int, tuple[Element, str]] = {}
    try:
        text, collected = vfs_text(model, namer=_namer(model, marks, written), limits=limits)
        compiled, found = _compile_marked(text, collected.files, marks)
    except ValueError as error:
        # MuJoCo's message may name a marker: compile() says it about the model as written
        compile_model(model, limits)
        raise CompileError(f"MuJoCo could not compile the model: {error}") from None
    return Compiled(compiled, _ids(compiled, found, written))


def ids_for_text(model: ModelBase, text: str, files: Mapping[str, bytes],
                 ) -> Mapping[int, tuple[Element, tuple[int, ...]]] | None:
    """The compiled ids of ``model``'s unnamed elements in a physics compiled from ``text``
    (dm_control's ``Physics.from_xml_string(model.to_xml_string(), ...)``), found by compiling
    the same text with markers; ``None`` if ``text`` is not ``model.to_xml_string()``."""
    marks: list[Element] = []
    written: dict[int, tuple[Element, str]] = {}
    marked = model_text(model, namer=_namer(model, marks, written))
    if _UNMARK.sub("", marked) != text:
        return None
    try:
        compiled, found = _compile_marked(marked, files, marks)
    except ValueError:
        return None
    return _ids(compiled, found, written)


def _namer(model: ModelBase, marks: list[Element], written: dict[int, tuple[Element, str]],
           ) -> Callable[[Writer], None]:
    """What marks every unnamed element that can be bound (into ``marks``) and notes the
    name the export gives those it names itself (into ``written``)."""

    def namer(writer: Writer) -> None:
        marked_class: dict[type[Element], bool] = {}  # per class: its unnamed ones are marked
        for element in _tree.iter_composed(model, True):
            cls = type(element)
            marked = marked_class.get(cls)
            if marked is None:  # (the world body, kind_of's one case not decided by the row,
                # has no name to be marked in)
                marked = marked_class[cls] = row_kind(cls) is not None
            if not marked or _tree.element_name(element) is not None:
                continue
            given = writer.given_names.get(id(element))
            file_attribute = grammar_facts().named_after_file.get(element.spec.namespace or "")
            if given is None and file_attribute is not None:
                # MuJoCo names it after its file, and refuses it unnamed in a spec
                given = element_file_stem(element, file_attribute)
            if given is not None:
                written[id(element)] = (element, writer.prefix(_tree.scope_of(element)) + given)
            else:
                writer.given_names[id(element)] = f"{_MARK}{len(marks)}-"
                marks.append(element)

    return namer


def _compile_marked(text: str, files: Mapping[str, bytes], marks: list[Element],
                    ) -> tuple[mujoco.MjModel, dict[int, tuple[Element, list[object]]]]:
    found: dict[int, tuple[Element, list[object]]] = {}

    def unmark(spec: mujoco.MjSpec) -> None:
        found.update(_unmark(spec, marks))

    # without marks, no spec to edit: MuJoCo's own route from text (the same model, faster)
    return compile_from_memory(text, files, unmark if marks else None), found


def _ids(compiled: mujoco.MjModel, found: dict[int, tuple[Element, list[object]]],
         written: dict[int, tuple[Element, str]]) -> dict[int, tuple[Element, tuple[int, ...]]]:
    import mujoco

    unnamed = {key: (element, tuple(_spec_id(obj) for obj in objects))
               for key, (element, objects) in found.items()}
    tables = binding_tables()
    for key, (element, name) in written.items():
        kind = kind_of(element)
        assert kind is not None
        objtype = getattr(mujoco.mjtObj, tables.kinds[kind].objtype)
        number = mujoco.mj_name2id(compiled, objtype, name)
        unnamed[key] = (element, (number,) if number >= 0 else ())
    return unnamed


def _unmark(spec: mujoco.MjSpec, marks: list[Element]) -> dict[int, tuple[Element, list[
        object]]]:
    """The spec's objects carrying each marker (set back to no name), by element."""
    found: dict[int, tuple[Element, list[object]]] = {}
    if not marks:
        return found
    kinds = {kind_of(element) for element in marks}
    tables = binding_tables()
    bodies: list[mujoco.MjsBody] | None = None  # read once, for the kinds bodies hold
    for kind in sorted(k for k in kinds if k is not None):
        spec_list = tables.kinds[kind].spec_list
        objects: Iterable[object]
        if hasattr(spec.worldbody, spec_list):  # geoms, joints, ...: body by body
            bodies = _bodies(spec) if bodies is None else bodies
            objects = bodies if spec_list == "bodies" else [
                obj for body in bodies for obj in cast("list[object]", getattr(body, spec_list))]
        else:
            objects = cast("Iterable[object]", getattr(spec, spec_list))
        for obj in objects:
            name = str(getattr(obj, "name", ""))
            match = _MARKED.search(name) if _MARK in name else None
            if match is None:
                continue
            element = marks[int(match.group(1))]
            found.setdefault(id(element), (element, []))[1].append(obj)
            setattr(obj, "name", "")
    return found


def _bodies(spec: mujoco.MjSpec) -> list[mujoco.MjsBody]:
    """The spec's bodies in the order of ``spec.bodies`` (depth first, the world first).

    The objects bodies hold are read body by body: MuJoCo finds each next object of a
    spec-wide list (``spec.geoms``) by a search of the whole tree, which is quadratic (21 ms
    for 1,000 geoms, 215 ms for 4,000; body by body: 4 ms, 66 ms)."""
    out: list[mujoco.MjsBody] = []
    stack = [spec.worldbody]
    while stack:
        body = stack.pop()
        out.append(body)
        stack.extend(reversed(body.bodies))
    return out


def _spec_id(obj: object) -> int:
    """The compiled id of an object of a compiled spec."""
    number = getattr(obj, "id", None)
    assert isinstance(number, int)
    return number

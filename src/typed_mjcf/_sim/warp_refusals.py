"""MuJoCo Warp, imported on first use; what of a model it refuses, element by element.

No list of what Warp supports is kept here: ``mujoco_warp.put_model`` is asked. It stops at
its first refusal, so each refusal is traced differentially: the model is compiled again
without one element (or with one setting of a global element such as ``<option>`` or
``<flag>`` left to its default), and an element is blamed when that changes what Warp says
(and no element inside it is blamed). The blamed elements are then taken out and Warp asked
again, until it takes the model or nothing more can be traced (then the refusal is reported
for the model as a whole).
"""

from __future__ import annotations

import copy
import importlib
from collections.abc import Callable
from dataclasses import dataclass
from types import ModuleType
from typing import TYPE_CHECKING, Final

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.errors import MjcfError
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._sim.bridge import compile_model
from typed_mjcf._sim.ids import kind_of

if TYPE_CHECKING:
    import mujoco

EXTRA: Final = "pip install 'typed-mjcf[warp]' (MuJoCo Warp, mujoco-warp==4.0.0)"


class WarpMissingError(MjcfError, ImportError):
    """MuJoCo Warp (the ``warp`` extra) is not installed."""


def warp_modules() -> tuple[ModuleType, ModuleType]:
    """``warp`` and ``mujoco_warp``, imported on first use (an optional extra)."""
    try:
        return importlib.import_module("warp"), importlib.import_module("mujoco_warp")
    except ImportError as error:
        raise WarpMissingError(f"MuJoCo Warp is not installed ({error}): {EXTRA}") from None


@dataclass(frozen=True, slots=True)
class Refusal:
    """One thing MuJoCo Warp refuses: the element (``path``; ``attribute`` for a global
    setting, else ``None``) and what Warp said."""

    path: str
    attribute: str | None
    message: str

    def __str__(self) -> str:
        where = f"{self.path} @{self.attribute}" if self.attribute else self.path
        return f"{where}: MuJoCo Warp refuses it: {self.message}"


Ask = Callable[["mujoco.MjModel"], "str | None"]


def warp_ask() -> Ask:
    """What the installed MuJoCo Warp says of a compiled model: its refusal, or ``None``."""
    put_model = warp_modules()[1].put_model

    def ask(model: mujoco.MjModel) -> str | None:
        try:
            put_model(model)
        except (NotImplementedError, ValueError) as error:
            return f"{type(error).__name__}: {error}"
        return None

    return ask


def warp_refusals(model: ModelBase, ask: Ask | None = None) -> list[Refusal]:
    """What of ``model`` MuJoCo Warp refuses (none: Warp takes it as it is). ``ask``: who
    is asked (the installed MuJoCo Warp by default)."""
    ask = warp_ask() if ask is None else ask
    work = copy.deepcopy(model)
    originals = dict(zip(map(id, _elements(work)), _elements(model), strict=True))
    found: list[Refusal] = []
    said = ask(compile_model(work))
    while said is not None:
        blamed = _blame(work, said, ask)
        if not blamed:
            found.append(Refusal(model.path or "(model)", None, said))
            break
        for element, attribute in blamed:
            found.append(Refusal(originals[id(element)].path, attribute, said))
        for element, attribute in blamed:
            _take_out(element, attribute)
        try:
            said = ask(compile_model(work))
        except MjcfError:
            break  # what is left does not compile: the refusals found are all that show
    return found


def _elements(model: ModelBase) -> list[Element]:
    return list(_tree.iter_composed(model, True))


def _candidates(model: ModelBase) -> list[tuple[int, str | None]]:
    """What may be taken out: each element MuJoCo compiles into an object, each other
    element below the root that has no children (a plugin, a flag), and each set
    attribute of a global element (one of no kind that holds none)."""
    out: list[tuple[int, str | None]] = []
    for at, element in enumerate(_elements(model)):
        if element.parent is None or element is model:
            continue
        kind = kind_of(element)
        if kind is not None and element.spec.holds_bodies and isinstance(
                element.parent, ModelBase):
            continue  # the world body
        if kind is not None or not list(_tree.children(element)):
            out.append((at, None))
        if kind is None and element.spec.id_attribute is None:
            out += [(at, name) for name in _tree.values(element)]
    return out


def _blame(model: ModelBase, said: str, ask: Ask) -> list[tuple[Element, str | None]]:
    """The elements (and global settings) whose removal alone changes what Warp says."""
    elements = _elements(model)
    blamed: list[tuple[Element, str | None]] = []
    for at, attribute in _candidates(model):
        trial = copy.deepcopy(model)
        twin = _elements(trial)[at]
        try:
            _take_out(twin, attribute)
            compiled = compile_model(trial)
        except (MjcfError, ValueError):
            continue  # cannot go alone (something refers to it): not judged
        if ask(compiled) != said:
            blamed.append((elements[at], attribute))
    # an element inside a blamed one is the cause, not its parent
    inner = {id(p) for e, a in blamed if a is None for p in _ancestors(e)}
    # and a blamed setting of an element, not the element
    inner |= {id(e) for e, a in blamed if a is not None}
    return [(e, a) for e, a in blamed if a is not None or id(e) not in inner]


def _ancestors(element: Element) -> list[Element]:
    out: list[Element] = []
    parent = element.parent
    while parent is not None:
        out.append(parent)
        parent = parent.parent
    return out


def _take_out(element: Element, attribute: str | None) -> None:
    if attribute is None:
        element.remove()
    else:
        spec = element.spec.by_name[attribute]
        setattr(element, spec.py_name, None)

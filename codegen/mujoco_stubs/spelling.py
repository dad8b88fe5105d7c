"""C++ spellings that pybind11 leaks into MuJoCo's signatures, mapped to the Python classes.

pybind11 writes a C++ type name where the Python class is registered in another module or
under another name (``mujoco::python::MjModelBodyViews`` is ``mujoco._structs
._MjModelBodyViews``; ``mjsBody_`` is ``mujoco._specs.MjsBody``). These are rules over the
spellings, not a list of names, so a new view class or spec element maps without an edit;
anything C++-looking that no rule maps stops the generator (:func:`check_no_cxx`).
"""

from __future__ import annotations

import keyword
import re

_RULES: tuple[tuple[re.Pattern[str], str], ...] = (
    # the named-access views: m.body("x") -> _MjModelBodyViews, d.joint(0) -> _MjDataJointViews
    (re.compile(r"\bmujoco::python::(MjModel|MjData)(\w+)Views\b"), r"mujoco._structs._\1\2Views"),
    (re.compile(r"\bmujoco::python::MjVfs\b"), "mujoco._specs.MjVfs"),
    # the C struct wrappers: MjWrapper<mjStatistic_> is the class for mjStatistic
    (re.compile(r"\bmujoco::python::_impl::MjWrapper<mj(\w+)_>"), r"mujoco._structs.Mj\1"),
    # spec element structs: mjsBody_ -> MjsBody
    (re.compile(r"\bmjs(\w+?)_\b"), r"mujoco._specs.Mjs\1"),
    # MjByteVec holds std::byte, for which pybind11 registers no Python conversion at all:
    # nothing can be passed or returned, so there is no truer type than Any.
    (re.compile(r"\bstd::byte\b"), "typing.Any"),
)

_CXX = re.compile(r"\bmj[a-zA-Z]+_\b")


def python_spelling(text: str) -> str:
    """``text`` (a draft stub) with every known C++ spelling replaced by its Python class."""
    for pattern, replacement in _RULES:
        text = pattern.sub(replacement, text)
    return "\n".join(_required_after_default(line) for line in text.split("\n")
                     if _KEYWORD_FIELD.match(line) is None)


# A field named after a Python keyword (``MjVisual.global``) can only be reached with
# getattr(); the bindings also spell it ``global_``, which the stub keeps.
_KEYWORD_FIELD = re.compile(rf"^\s+({'|'.join(keyword.kwlist)}): ")


def _split_top_level(text: str) -> list[str]:
    """``text`` split at the commas outside brackets and quotes."""
    parts: list[str] = []
    depth, start, quote = 0, 0, ""
    for i, ch in enumerate(text):
        if quote:
            quote = "" if ch == quote else quote
        elif ch in "\"'":
            quote = ch
        elif ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return parts


_DEF = re.compile(r"^(?P<head>\s*def \w+\()(?P<args>.*)(?P<tail>\) -> .*:)$")


def _required_after_default(line: str) -> str:
    """Drop a default that a required parameter follows (not valid Python).

    pybind11 lets a C++ binding give ``resolve_orientation(degree, sequence=None,
    orientation)``; the ``None`` can never be used positionally, so the stub requires it.
    """
    match = _DEF.match(line)
    if match is None:
        return line
    args = _split_top_level(match["args"])
    positional: list[str] = []
    for arg in args:
        if arg.strip().startswith("*"):
            break
        positional.append(arg)
    for i, arg in enumerate(positional):
        later = positional[i + 1:]
        if "=" in arg and any("=" not in a.split(":")[-1] and "=" not in a for a in later):
            args[i] = arg.split("=")[0].rstrip()
    return match["head"] + ",".join(args) + match["tail"]


def cxx_left(annotation: str) -> str | None:
    """A C struct name left in ``annotation`` (valid Python, so the parser let it through)."""
    match = _CXX.search(annotation)
    return None if match is None else match.group(0)

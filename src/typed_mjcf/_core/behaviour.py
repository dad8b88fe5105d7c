"""The one switch between the typed API's choices and dm_control's observable behaviour.

``install_as_dm_control_mjcf()`` turns it on (README "Coming from dm_control.mjcf" lists
what it changes); every module that behaves differently reads :func:`dm_control_behaviour`.
Off, the typed API keeps its own choices: read-only arrays, once-only children created on
first access, readable file names, unnamed elements without identifiers.
"""

from __future__ import annotations

from typing import Final

# [on]: a list rather than a global statement, so readers import the list once
_STATE: Final[list[bool]] = [False]


def dm_control_behaviour() -> bool:
    """Whether dm_control's behaviour is on (see the module docstring)."""
    return _STATE[0]


def set_dm_control_behaviour(on: bool) -> bool:
    """Turn dm_control's behaviour on or off; return the previous setting."""
    previous = _STATE[0]
    _STATE[0] = on
    return previous


STATE: Final = _STATE

# dm_control's schema puts some kinds in one namespace of its own (its names for unnamed
# elements count them together: //unnamed_contact_0 for a <pair> or an <exclude>)
_DM_CONTROL_NAMESPACES: Final = {"pair": "contact", "exclude": "contact", "flex": "deformable",
                                 "skin": "deformable"}


def dm_control_namespace(namespace: str) -> str:
    """The name of ``namespace`` in dm_control's schema."""
    return _DM_CONTROL_NAMESPACES.get(namespace, namespace)  # for the hot paths of the tree: ``STATE[0]`` without a call

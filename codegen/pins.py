"""The MuJoCo pins that move with schema/ on release day (``python -m codegen generate``).

schema/mjcf.json says which MuJoCo release the bindings describe; noxfile.py reads it from
there. Two pins in pyproject.toml must agree with it, and the generator rewrites them:

* the dev extra's ``mujoco==X``: the package users have and the one dm_control (a test
  dependency) requires, so pip installs that release alone; pinning ``mujoco-core`` instead
  lets pip satisfy dm_control with an older ``mujoco`` (3.x has no ``mujoco-core``) installed
  over the core, which is a broken ``import mujoco``;
* the runtime dependency range ``mujoco<B`` (or ``mujoco>=A,<B``): its upper bound is raised to
  the next minor release when X is at or past it (a lower bound, when there is one, is moved
  by hand; today there is none: see the comment on the dependency in pyproject.toml).
"""

from __future__ import annotations

import re
from pathlib import Path

from codegen.releases import version_key

PYPROJECT = Path(__file__).resolve().parents[1] / "pyproject.toml"
# "mujoco==4.0.0" in the dev extra (the only exact MuJoCo pin of pyproject.toml)
_DEV_PIN = re.compile(r'"mujoco(?:-core)?==(?P<version>[0-9][0-9.]*)"')
# "mujoco<4.1" or "mujoco>=4.0.0,<4.1" in [project] dependencies
_RANGE = re.compile(r'"mujoco(?:>=(?P<low>[0-9][0-9.]*),)?<(?P<high>[0-9][0-9.]*)"')


class PinError(ValueError):
    """pyproject.toml does not hold the pins in the form this module rewrites."""


def read(text: str) -> tuple[str, tuple[str, str]]:
    """The dev extra's MuJoCo release and the dependency range ``(low, high)`` (``low`` is
    empty when the range has no lower bound)."""
    pins = _DEV_PIN.findall(text)
    ranges = _RANGE.findall(text)
    if len(pins) != 1 or len(ranges) != 1:
        raise PinError('pyproject.toml: expected one "mujoco==X" pin (dev extra) and one '
                       '"mujoco<B" (or "mujoco>=A,<B") dependency; '
                       f"found {len(pins)} and {len(ranges)}")
    low, high = ranges[0]
    return pins[0], (low, high)


def moved(text: str, version: str) -> tuple[str, list[str]]:
    """``text`` (pyproject.toml) with the pins moved to ``version``, and what moved."""
    pin, (low, high) = read(text)
    changes: list[str] = []
    if _DEV_PIN.search(text) and (pin != version or '"mujoco-core==' in text):
        text = _DEV_PIN.sub(f'"mujoco=={version}"', text)
        changes.append(f"dev extra: mujoco=={pin} -> mujoco=={version}")
    if version_key(version) >= version_key(high):
        major, minor = version_key(version)[:2]
        new_high = f"{major}.{minor + 1}"
        lower = f">={low}," if low else ""
        text = _RANGE.sub(f'"mujoco{lower}<{new_high}"', text)
        changes.append(f"dependencies: mujoco{lower}<{high} -> mujoco{lower}<{new_high}")
    return text, changes


def disagreements(text: str, version: str) -> list[str]:
    """How the pins of ``text`` disagree with ``version`` (what schema/ describes)."""
    pin, (low, high) = read(text)
    problems: list[str] = []
    if pin != version or '"mujoco-core==' in text:
        problems.append(f"the dev extra pins {pin}, not mujoco=={version}")
    below = bool(low) and version_key(version) < version_key(low)
    if below or version_key(version) >= version_key(high):
        lower = f">={low}," if low else ""
        problems.append(f"the dependency range mujoco{lower}<{high} leaves out {version}")
    return problems


def update(version: str, path: Path = PYPROJECT) -> list[str]:
    """Move the pins of ``path`` to ``version``; what moved."""
    text, changes = moved(path.read_text(encoding="utf-8"), version)
    if changes:
        path.write_text(text, encoding="utf-8", newline="\n")
    return changes

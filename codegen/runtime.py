"""Core modules of the runtime the generator reads, loaded by their path.

A core module that imports nothing from ``typed_mjcf`` (``_core/language``: the language
facts' declaration; ``_core/doclines``: the layout of ``add_<tag>()`` docstrings) is loaded on its own,
under its own name, without the package's ``__init__``: that imports the generated package,
which a change the generator is about to render (a new language fact) may have made stale.
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

SRC = Path(__file__).resolve().parent.parent / "src" / "typed_mjcf"


def core_module(name: str) -> ModuleType:
    """``typed_mjcf.<name>`` (``name`` a path under the package: ``_core/language``), as
    imported already or loaded from its file."""
    qualified = "typed_mjcf." + name.replace("/", ".")
    if qualified in sys.modules:
        return sys.modules[qualified]
    spec = importlib.util.spec_from_file_location(qualified, SRC / f"{name}.py")
    if spec is None or spec.loader is None:
        raise ImportError(f"no runtime module {qualified} at {SRC}")
    module = importlib.util.module_from_spec(spec)
    sys.modules[qualified] = module
    spec.loader.exec_module(module)
    return module

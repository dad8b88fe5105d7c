"""typed-mjcf: a statically typed, code-generated builder for MuJoCo's MJCF models.

    import typed_mjcf as mjcf

    model = mjcf.RootElement(model="arm")
    arm = model.worldbody.add_body(name="upper_arm", pos=(0, 0, 1))
    arm.add_geom(type="capsule", size=(0.04, 0.2))
    print(model.to_xml_string())
"""

__version__ = "0.1.0"

from typing import TYPE_CHECKING as _TYPE_CHECKING
from typing import Final as _Final

from typed_mjcf._base import Element, ModelRoot
from typed_mjcf._build import compiled_modules as _compiled_modules
from typed_mjcf._core.behaviour import Behaviour, behaviour, current_behaviour, set_behaviour
from typed_mjcf._core.names import NameScope
from typed_mjcf._core.tree import ElementList
from typed_mjcf._generated import elements as _elements
from typed_mjcf._generated.elements import *
from typed_mjcf._model.resource_limits import CompileLimits, RenderLimits
from typed_mjcf._model.traversal import (
    commit_defaults,
    get_attachment_frame,
    get_frame_freejoint,
    get_frame_joints,
    get_freejoint,
)
from typed_mjcf._sim.notebook import set_notebook_display
from typed_mjcf._sim.png import encode_png
from typed_mjcf._sim.preview import VIEWS, FreeView
from typed_mjcf.assets import Asset
from typed_mjcf.errors import (
    BindingError,
    ChildError,
    CompileError,
    DuplicateIdentifierError,
    ExportError,
    FileAccessError,
    FileReadError,
    Finding,
    IgnoredAttributeWarning,
    IllegalChildError,
    InvalidReferenceError,
    InvalidTypeError,
    InvalidValueError,
    MjcfError,
    NotParametricError,
    ParseError,
    PhysicsError,
    RenderError,
    UnbatchedWarning,
    UnknownAttributeError,
    ValidationError,
)
from typed_mjcf.io import (
    FileAccess,
    ParseLimits,
    export_with_assets,
    export_with_assets_as_zip,
    from_file,
    from_path,
    from_spec,
    from_xml_string,
    from_zip,
)

if _TYPE_CHECKING:
    from typed_mjcf import physics as physics
    from typed_mjcf.physics import Physics

PREFIX_SEPARATOR: _Final[str] = "/"  # dm_control's name for the scope separator of attached models

__all__ = [
    "COMPILED",
    "PREFIX_SEPARATOR",
    "VIEWS",
    "Asset",
    "Behaviour",
    "BindingError",
    "ChildError",
    "CompileError",
    "CompileLimits",
    "DuplicateIdentifierError",
    "Element",
    "ElementList",
    "ExportError",
    "FileAccess",
    "FileAccessError",
    "FileReadError",
    "Finding",
    "FreeView",
    "IgnoredAttributeWarning",
    "IllegalChildError",
    "InvalidReferenceError",
    "InvalidTypeError",
    "InvalidValueError",
    "MjcfError",
    "ModelRoot",
    "NameScope",
    "NotParametricError",
    "ParseError",
    "ParseLimits",
    "Physics",
    "PhysicsError",
    "RenderError",
    "RenderLimits",
    "UnbatchedWarning",
    "UnknownAttributeError",
    "ValidationError",
    "behaviour",
    "commit_defaults",
    "current_behaviour",
    "encode_png",
    "export_with_assets",
    "export_with_assets_as_zip",
    "from_file",
    "from_path",
    "from_spec",
    "from_xml_string",
    "from_zip",
    "get_attachment_frame",
    "get_frame_freejoint",
    "get_frame_joints",
    "get_freejoint",
    "set_behaviour",
    "set_notebook_display",
]
__all__ += _elements.__all__

from typed_mjcf._dmcompat import install as install_as_dm_control_mjcf

__all__ += ["install_as_dm_control_mjcf"]

# Which build runs: the modules mypyc compiled (pyproject's list, in a wheel built with
# TYPED_MJCF_COMPILE=1), () in the pure-Python build. Every module compiled is imported by now.
COMPILED: _Final[tuple[str, ...]] = _compiled_modules()

# Simulation imports mujoco, the heaviest import there is: loaded when first used.
_PHYSICS_NAMES: _Final = frozenset({"Physics", "physics"})


def __getattr__(name: str) -> object:
    if name in _PHYSICS_NAMES:
        import importlib

        module = importlib.import_module("typed_mjcf.physics")
        return module if name == "physics" else getattr(module, name)
    raise AttributeError(f"module 'typed_mjcf' has no attribute {name!r}")

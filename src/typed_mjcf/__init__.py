"""typed-mjcf: a statically typed, code-generated builder for MuJoCo's MJCF models.

    import typed_mjcf as mjcf

    model = mjcf.RootElement(model="arm")
    arm = model.worldbody.add_body(name="upper_arm", pos=(0, 0, 1))
    arm.add_geom(type="capsule", size=(0.04, 0.2))
    print(model.to_xml_string())
"""

__version__ = "0.1.0"  # first: the generated package reads it while this module initialises

from typed_mjcf_generated import elements as _elements
from typed_mjcf_generated.elements import *

from typed_mjcf._element import Element
from typed_mjcf._root import ModelRoot
from typed_mjcf._validate import Finding, ValidationError
from typed_mjcf.assets import Asset
from typed_mjcf.errors import (
    ChildError,
    CompileError,
    DuplicateIdentifierError,
    ExportError,
    InvalidTypeError,
    InvalidValueError,
    MjcfError,
    ParseError,
    UnknownAttributeError,
)
from typed_mjcf.io import (
    ParseLimits,
    export_with_assets,
    from_file,
    from_path,
    from_spec,
    from_xml_string,
)

__all__ = [
    "Asset",
    "ChildError",
    "CompileError",
    "DuplicateIdentifierError",
    "Element",
    "ExportError",
    "Finding",
    "InvalidTypeError",
    "InvalidValueError",
    "MjcfError",
    "ModelRoot",
    "ParseError",
    "ParseLimits",
    "UnknownAttributeError",
    "ValidationError",
    "export_with_assets",
    "from_file",
    "from_path",
    "from_spec",
    "from_xml_string",
]
__all__ += _elements.__all__

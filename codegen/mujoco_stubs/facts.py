"""Hand-kept typing facts: what neither pybind11's signatures nor the source annotations say.

Keys are ``module:Qualified.name``; parameters add ``(name)``. Every entry must match a
definition in the drafts (a stale entry fails the build, as does a definition left untyped),
so a new MuJoCo release either regenerates cleanly or names exactly what needs a decision.
Each entry says why it is needed; ``Any`` appears only where MuJoCo itself is dynamic.
"""

from __future__ import annotations

import ast

from codegen.mujoco_stubs.syntax import definitions, parse_expr

_MJ = "mujoco._structs"
_ARRAY = "numpy.typing.NDArray[numpy.float64]"

# Return annotations.
RETURNS: dict[str, str] = {
    # pybind11 returns py::object where the class lives in another extension module; these
    # are what the functions return (checked at run time by tests/typing's positive cases).
    "mujoco._specs:MjSpec.compile": f"{_MJ}.MjModel",
    "mujoco._specs:MjSpec.recompile": f"{_MJ}.MjData",
    # unannotated in mujoco/__init__.py: attribute lookup on a group of bound elements
    # returns whatever each element's view holds, in a list (MuJoCo itself is dynamic here)
    "mujoco:_MjBindModel.__getattr__": "list[typing.Any]",
    "mujoco:_MjBindModel.__setattr__": "None",
    "mujoco:_MjBindData.__getattr__": "list[typing.Any]",
    "mujoco:_MjBindData.__setattr__": "None",
    # unannotated in minimize.py; from the code
    "mujoco.minimize:Norm.grad_hess": "tuple[numpy.typing.NDArray[typing.Any], "
                                      "numpy.typing.NDArray[typing.Any]]",
    # Norm.value says np.float64, Quadratic.value returns a Python float (``.item()``):
    # float covers both, and np.float64 is a float
    "mujoco.minimize:Norm.value": "float",
    "mujoco.minimize:Quadratic.value": "float",
    "mujoco.minimize:Quadratic.grad_hess": "tuple[numpy.typing.NDArray[typing.Any], "
                                           "numpy.typing.NDArray[typing.Any]]",
    "mujoco.minimize:check_norm": "None",
    # unannotated in rendering/classic/renderer.py; from the code
    "mujoco.rendering.classic.renderer:Renderer.model": f"{_MJ}.MjModel",
    "mujoco.rendering.classic.renderer:Renderer.height": "int",
    "mujoco.rendering.classic.renderer:Renderer.width": "int",
    "mujoco.rendering.classic.renderer:Renderer.update_scene": "None",
    "mujoco.rendering.classic.renderer:Renderer.__enter__": "typing.Self",
    # unannotated in rollout.py; both return (state, sensordata), float64 arrays it allocates
    "mujoco.rollout:Rollout.__enter__": "typing.Self",
    "mujoco.rollout:Rollout.rollout": f"tuple[{_ARRAY}, {_ARRAY}]",
    "mujoco.rollout:rollout": f"tuple[{_ARRAY}, {_ARRAY}]",
    # unannotated in viewer.py; from the code (None once the viewer window has closed)
    "mujoco.viewer:Handle.cam": f"{_MJ}.MjvCamera",
    "mujoco.viewer:Handle.opt": f"{_MJ}.MjvOption",
    "mujoco.viewer:Handle.perturb": f"{_MJ}.MjvPerturb",
    "mujoco.viewer:Handle.user_scn": f"{_MJ}.MjvScene | None",
    "mujoco.viewer:Handle.m": f"{_MJ}.MjModel | None",
    "mujoco.viewer:Handle.d": f"{_MJ}.MjData | None",
    "mujoco.viewer:Handle.viewport": f"{_MJ}.MjrRect | None",
    "mujoco.viewer:Handle.set_figures": "None",
    "mujoco.viewer:Handle.set_texts": "None",
    "mujoco.viewer:Handle.set_images": "None",
    "mujoco.viewer:Handle.lock": "contextlib.AbstractContextManager[None]",
    "mujoco.viewer:Handle.sync": "None",
    "mujoco.viewer:Handle.update_hfield": "None",
    "mujoco.viewer:Handle.update_mesh": "None",
    "mujoco.viewer:Handle.update_texture": "None",
    "mujoco.viewer:Handle.__enter__": "typing.Self",
    "mujoco.viewer:_MjPythonBase.launch_on_ui_thread": "None",
}

# Parameter annotations.
PARAMS: dict[str, str] = {
    # pybind11 says object: the models and data the spec writes back into / recompiles
    "mujoco._specs:MjSpec.copy_back(model)": f"{_MJ}.MjModel",
    "mujoco._specs:MjSpec.recompile(m)": f"{_MJ}.MjModel",
    "mujoco._specs:MjSpec.recompile(d)": f"{_MJ}.MjData",
    # py::dict in the binding (a dict, not any mapping): file name -> contents
    "mujoco._specs:MjSpec.from_string(assets)": "dict[str, bytes] | None",
    "mujoco._specs:MjSpec.from_file(assets)": "dict[str, bytes] | None",
    # a site or frame of the parent spec to attach at, or its name
    "mujoco._specs:MjSpec.attach(site)": "mujoco._specs.MjsSite | str | None",
    "mujoco._specs:MjSpec.attach(frame)": "mujoco._specs.MjsFrame | str | None",
    # add_freejoint(**kwargs) forwards to add_joint's keywords (name=..., group=...):
    # the values are as varied as add_joint's parameters
    "mujoco._specs:MjsBody.add_freejoint(kwargs)": "typing.Any",
    # viewer.py annotates it with _Simulate, a private alias stubgen leaves out
    "mujoco.viewer:Handle.__init__(sim)": "mujoco._simulate.Simulate",
    "mujoco.glfw:GLContext.__init__(max_width)": "int",
    "mujoco.glfw:GLContext.__init__(max_height)": "int",
}

# Attribute annotations (module or class level).
ATTRIBUTES: dict[str, str] = {
    # mj_versionString(), os.path.join(...) at import
    "mujoco:__version__": "str",
    "mujoco:HEADERS_DIR": "str",
    "mujoco:PLUGINS_DIR": "str",
    "mujoco:PLUGIN_HANDLES": "list[ctypes.CDLL]",
    # float64 in every published wheel (MJTNUM_BYTES == 8); the array fields say so too
    "mujoco:MJTNUM_DTYPE": "type[numpy.float64]",
    # py::dict in the binding: file name -> contents
    "mujoco._specs:MjSpec.assets": "dict[str, bytes]",
    "mujoco.batch:SimulationError.ids": "numpy.typing.NDArray[typing.Any]",
    "mujoco.batch:Batch.model": f"{_MJ}.MjModel",
    "mujoco.batch:Batch.state": _ARRAY,
    "mujoco.batch:Batch.warning": "numpy.typing.NDArray[typing.Any]",
    "mujoco.batch:Batch.status": "numpy.typing.NDArray[typing.Any]",
    "mujoco.batch:DATA_FIELDS": "frozenset[str]",
    "mujoco.batch:MODEL_FIELDS": "frozenset[str]",
    "mujoco.rollout:Rollout.nthread": "int",
    "mujoco.rollout:Rollout.rollout_": "mujoco._rollout.Rollout | None",
    "mujoco.rollout:persistent_rollout": "mujoco.rollout.Rollout | None",
    "mujoco.viewer:PERCENT_REALTIME": "tuple[float, ...]",
}

# Whole definitions replaced by the given source ("" deletes the definition).
REPLACE: dict[str, str] = {
    # locals of the macOS check at the top of mujoco/__init__.py, not API
    "mujoco:proc_translated": "",
    "mujoco:is_rosetta": "",
    # stubgen keeps only "MjStruct: TypeAlias"; the union is the spec element classes
    "mujoco:MjStruct": "MjStruct: typing.TypeAlias = (" + " | ".join(
        f"_specs.Mjs{name}" for name in (
            "Body", "Frame", "Geom", "Joint", "Light", "Material", "Site", "Mesh", "Skin",
            "Texture", "Text", "Tuple", "Camera", "Flex", "HField", "Key", "Numeric", "Pair",
            "Exclude", "Equality", "Tendon", "Sensor", "Actuator", "Plugin")) + ")",
    # type aliases, which stubgen cannot spell
    "mujoco.batch:Ids": "Ids: typing.TypeAlias = numpy.typing.ArrayLike | None",
    "mujoco.batch:RecordItem": "RecordItem: typing.TypeAlias = str | int | mujoco.mjtState",
    "mujoco.viewer:CallbackType": "CallbackType: typing.TypeAlias = collections.abc.Callable["
                                  f"[{_MJ}.MjModel, {_MJ}.MjData], None]",
    "mujoco.viewer:LoaderType": "LoaderType: typing.TypeAlias = collections.abc.Callable["
                                f"[], tuple[{_MJ}.MjModel, {_MJ}.MjData]]",
    # GLContext is the class of the back end MUJOCO_GL picks at import (glfw, egl, osmesa,
    # cgl), all with the same interface; the stubs name the glfw one, the default.
    "mujoco.rendering.classic.gl_context:GLContext":
        "from mujoco.glfw import GLContext as GLContext",
    "mujoco.rendering.classic.gl_context:_MissingGLContext": "",
    "mujoco.rendering.classic.renderer:GLContext": "",
}

_used: set[str] = set()


def _table_keys() -> set[str]:
    return set(RETURNS) | set(PARAMS) | set(ATTRIBUTES) | set(REPLACE)


def reset() -> None:
    """Forget which facts were used (start of a build)."""
    _used.clear()


def unused() -> list[str]:
    """Facts that matched nothing: the name moved or went away in this MuJoCo."""
    return [f"facts.py: {key!r} matches no definition" for key in sorted(_table_keys() - _used)]


def _statements(source: str) -> list[ast.stmt]:
    return ast.parse(source).body


def apply(tree: ast.Module, module: str) -> list[str]:
    """Apply every fact about ``module`` to ``tree``; problems as messages."""
    problems: list[str] = []
    for key, node, body in list(definitions(tree, module)):
        if key in REPLACE:
            _used.add(key)
            at = body.index(node)
            body[at:at + 1] = _statements(REPLACE[key])
            continue
        if isinstance(node, ast.FunctionDef):
            if key in RETURNS:
                _used.add(key)
                node.returns = parse_expr(RETURNS[key])
            for arg in (*node.args.posonlyargs, *node.args.args, *node.args.kwonlyargs,
                        *filter(None, (node.args.vararg, node.args.kwarg))):
                param_key = f"{key}({arg.arg})"
                if param_key in PARAMS:
                    _used.add(param_key)
                    arg.annotation = parse_expr(PARAMS[param_key])
        elif isinstance(node, ast.AnnAssign | ast.Assign) and key in ATTRIBUTES:
            _used.add(key)
            target = node.target if isinstance(node, ast.AnnAssign) else node.targets[0]
            assert isinstance(target, ast.Name)  # definitions() yields named targets only
            replacement = ast.AnnAssign(target=target, annotation=parse_expr(ATTRIBUTES[key]),
                                        value=None, simple=1)
            body[body.index(node)] = replacement
    return problems

"""The README's pictures of the examples, made by ``model.render()``: ``nox -s pictures``
(or ``python -m tests.pictures``) writes them to ``examples/pictures/``;
``tests/test_pictures.py`` renders them again and checks the committed files are current.

Each picture is one example's model (built by its own function) with the view that shows it.
"""

from __future__ import annotations

import argparse
import importlib.util
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from types import ModuleType

import numpy as np
from numpy.typing import NDArray

import typed_mjcf as mjcf

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
FOLDER = EXAMPLES / "pictures"


@dataclass(frozen=True)
class Picture:
    """``script``'s model, from ``builder`` (a function of the script, or a callable taking
    the script's module), rendered with ``options``."""

    script: str
    builder: str | Callable[[ModuleType], mjcf.RootElement]
    size: tuple[int, int] = (320, 240)
    camera: mjcf.FreeView | None = None
    keyframe: str | None = None
    time: float = 0.0
    views: tuple[str, ...] | None = None
    note: str = field(default="", compare=False)


def _scene(module: ModuleType) -> mjcf.RootElement:
    scene: mjcf.RootElement = module.make_scene()[0]
    return scene


PICTURES: dict[str, Picture] = {
    "demo.png": Picture("demo.py", "build_arm", size=(480, 360),
                        views=("front", "side", "top", "iso")),
    "quadruped.png": Picture("quadruped.py", "build", keyframe="stand", time=0.5,
                             camera=mjcf.FreeView(azimuth=135, elevation=-20, distance=1.6,
                                                  lookat=(0.0, 0.0, 0.3))),
    "arm_gripper.png": Picture("arm_gripper.py", _scene),
    "composition_scene.png": Picture("composition_scene.py", "build"),
}


def example(script: str) -> ModuleType:
    """An example script as a module (its ``main()`` not run)."""
    name = f"_example_{Path(script).stem}"
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / script)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def model_of(picture: Picture) -> mjcf.RootElement:
    module = example(picture.script)
    if isinstance(picture.builder, str):
        built: mjcf.RootElement = getattr(module, picture.builder)()
        return built
    return picture.builder(module)


def render(picture: Picture, model: mjcf.RootElement | None = None) -> NDArray[np.uint8]:
    """The picture, of ``model`` when given (a changed model, say) else the example's."""
    width, height = picture.size
    return (model or model_of(picture)).render(
        picture.camera, width=width, height=height, keyframe=picture.keyframe,
        time=picture.time, views=picture.views)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", type=Path, default=FOLDER, help="where to write them")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    from typed_mjcf._sim.png import encode_png

    for name, picture in PICTURES.items():
        path = args.out / name
        path.write_bytes(encode_png(render(picture)))
        print(f"wrote {path.relative_to(ROOT) if path.is_relative_to(ROOT) else path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

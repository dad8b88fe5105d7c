"""Offscreen rendering with mujoco.Renderer, and the visualisation structs it wraps.

Type-checked only where it needs an OpenGL context (``render_frames``); the structs are
made for real by ``scene_structs``.
"""

from __future__ import annotations

from typing import assert_type

import mujoco
import numpy as np
import numpy.typing as npt

XML = """
<mujoco>
  <worldbody>
    <light pos="0 0 3"/>
    <camera name="front" pos="0 -2 1" xyaxes="1 0 0 0 1 2"/>
    <body name="box" pos="0 0 0.5"><freejoint/><geom type="box" size="0.1 0.1 0.1"/></body>
  </worldbody>
</mujoco>
"""


def render_frames(m: mujoco.MjModel, d: mujoco.MjData) -> list[npt.NDArray[np.uint8]]:
    frames: list[npt.NDArray[np.uint8]] = []
    option = mujoco.MjvOption()
    option.flags[mujoco.mjtVisFlag.mjVIS_CONTACTPOINT] = True
    with mujoco.Renderer(m, height=240, width=320) as renderer:
        assert_type(renderer, mujoco.Renderer)
        assert_type(renderer.height, int)
        for _ in range(3):
            mujoco.mj_step(m, d)
            renderer.update_scene(d, camera="front", scene_option=option)
            pixels = renderer.render()
            frames.append(pixels.astype(np.uint8))
        renderer.enable_depth_rendering()
        renderer.update_scene(d, camera=0)
        depth = renderer.render()
        assert depth.ndim == 2
        renderer.disable_depth_rendering()
        scene: mujoco.MjvScene = renderer.scene
        assert scene.ngeom >= 0
    return frames


def scene_structs(m: mujoco.MjModel, d: mujoco.MjData) -> int:
    camera = mujoco.MjvCamera()
    mujoco.mjv_defaultFreeCamera(m, camera)
    camera.distance = 3.0
    camera.type = mujoco.mjtCamera.mjCAMERA_FREE
    option = mujoco.MjvOption()
    mujoco.mjv_defaultOption(option)
    perturb = mujoco.MjvPerturb()
    scene = mujoco.MjvScene(m, maxgeom=1000)
    mujoco.mjv_updateScene(m, d, option, perturb, camera, mujoco.mjtCatBit.mjCAT_ALL, scene)
    assert_type(scene.ngeom, int)
    rect = mujoco.MjrRect(0, 0, 320, 240)
    assert_type(rect.width, int)
    geom = scene.geoms[0]
    assert_type(geom.pos, npt.NDArray[np.float32])
    return scene.ngeom


def context_type(context: mujoco.MjrContext, rect: mujoco.MjrRect, scene: mujoco.MjvScene
                 ) -> None:
    mujoco.mjr_render(rect, scene, context)
    rgb = np.zeros((rect.height, rect.width, 3), dtype=np.uint8)
    mujoco.mjr_readPixels(rgb, None, rect, context)


def main() -> int:
    m = mujoco.MjModel.from_xml_string(XML)
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    assert callable(mujoco.Renderer)
    return scene_structs(m, d)


if __name__ == "__main__":
    print(main())

"""The passive viewer, typed (needs a display, so only type-checked: see ``watch``)."""

from __future__ import annotations

import time

import mujoco
import mujoco.viewer


def watch(m: mujoco.MjModel, d: mujoco.MjData, seconds: float) -> None:
    def on_key(keycode: int) -> None:
        print(keycode)

    with mujoco.viewer.launch_passive(m, d, key_callback=on_key) as viewer:
        viewer.cam.distance = 2.0
        viewer.opt.flags[mujoco.mjtVisFlag.mjVIS_JOINT] = True
        start = time.time()
        while viewer.is_running() and time.time() - start < seconds:
            with viewer.lock():
                mujoco.mj_step(m, d)
            viewer.sync()
        model = viewer.m
        if model is not None:
            print(model.nbody)


def launch_blocking(m: mujoco.MjModel) -> None:
    mujoco.viewer.launch(m, show_left_ui=False)


if __name__ == "__main__":
    assert callable(watch)

"""The README's pictures of the examples (``examples/pictures/``) are current: each is
rendered again from its example and compared with the committed file.

Software rendering is not bit-exact across machines (Mesa versions, CPU features), so
"current" means close: a small mean difference and almost no pixel far off. A change to an
example's model (a colour, a part moved) is far outside that, as the last test shows.
``nox -s pictures`` writes them again.
"""

from __future__ import annotations

import numpy as np
import pytest
from numpy.typing import NDArray

from tests.pictures import FOLDER, PICTURES, model_of, render
from tests.render.scenes import decode_png

# Another Mesa or CPU moves a few edge and shadow pixels; the changes below move about 1% of
# the pixels far off (mean 0.9 to 1.2): they fail by a factor of three or more.
MEAN_TOLERANCE = 0.5  # mean absolute difference per channel, out of 255
FAR_OFF = 48  # a pixel this far off on some channel ...
FAR_OFF_SHARE = 0.003  # ... may be at most this share of the pixels


def difference(a: NDArray[np.uint8], b: NDArray[np.uint8]) -> tuple[float, float]:
    """Mean absolute difference, and the share of pixels far off."""
    assert a.shape == b.shape, f"sizes differ: {a.shape} and {b.shape}"
    delta = np.abs(a.astype(np.int32) - b.astype(np.int32))
    return float(delta.mean()), float((delta.max(axis=2) > FAR_OFF).mean())


def current(a: NDArray[np.uint8], b: NDArray[np.uint8]) -> bool:
    mean, far = difference(a, b)
    return mean <= MEAN_TOLERANCE and far <= FAR_OFF_SHARE


def committed(name: str) -> NDArray[np.uint8]:
    path = FOLDER / name
    assert path.is_file(), f"{path} is missing: run nox -s pictures"
    return decode_png(path.read_bytes())


def test_every_picture_is_committed_shown_and_none_is_left_over() -> None:
    assert {p.name for p in FOLDER.glob("*.png")} == set(PICTURES)
    root = FOLDER.parent.parent
    page = (root / "docs" / "guide" / "previews.md").read_text(encoding="utf-8")
    for name in PICTURES:
        assert f"](../../examples/pictures/{name})" in page, \
            f"docs/guide/previews.md does not show {name}"
    readme = (root / "README.md").read_text(encoding="utf-8")
    assert "](examples/pictures/demo.png)" in readme, "the README shows the demo's picture"


@pytest.mark.parametrize("name", list(PICTURES))
def test_the_picture_is_current(name: str) -> None:
    fresh = render(PICTURES[name])
    mean, far = difference(committed(name), fresh)
    assert current(committed(name), fresh), (
        f"{name} is out of date (mean difference {mean:.2f}, {far:.1%} of pixels far off): "
        "run nox -s pictures")


def test_a_changed_example_is_not_current() -> None:
    """What the check would say if the quadruped's legs were another colour, or its torso
    were longer: out of date."""
    picture = PICTURES["quadruped.png"]
    recoloured = model_of(picture)
    leg = recoloured.default.find_all("default")
    for default in leg:
        if default.class_ == "robot":
            default.geom.rgba = (0.6, 0.45, 0.3, 1)
    assert not current(committed("quadruped.png"), render(picture, recoloured))
    longer = model_of(picture)
    torso = longer.find("geom", "torso")
    assert torso is not None
    torso.size = (0.32, 0.1, 0.04)
    assert not current(committed("quadruped.png"), render(picture, longer))

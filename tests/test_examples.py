"""The scripts in ``examples/`` run as a user runs them, and what they print is physically
right: each script in a fresh process, its printed figures read back and checked against
what the model is built to do, and the XML it writes compiled again from disk.

Their type checking is in ``test_readme.py`` (one batched run with the README's code).
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import mujoco

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
TESTED = {"demo.py", "quadruped.py", "arm_gripper.py", "composition_scene.py"}


def run(script: str, out: Path) -> str:
    result = subprocess.run([sys.executable, str(EXAMPLES / script), "--out", str(out)],
                            capture_output=True, text=True, timeout=600, check=False)
    assert result.returncode == 0, f"{script} failed:\n{result.stdout}\n{result.stderr}"
    assert not result.stderr, f"{script} wrote to stderr:\n{result.stderr}"
    return result.stdout


def numbers(pattern: str, text: str) -> list[float]:
    """The groups of ``pattern``'s first match in ``text``, as floats."""
    match = re.search(pattern, text)
    assert match is not None, f"no line matching {pattern!r} in:\n{text}"
    return [float(group) for group in match.groups()]


def compiles_from_disk(path: Path) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_path(str(path))


def test_every_example_is_tested() -> None:
    assert {p.name for p in EXAMPLES.glob("*.py")} == TESTED


def test_demo_reaches_its_targets(tmp_path: Path) -> None:
    out = run("demo.py", tmp_path)
    for joint in ("shoulder", "elbow"):
        target, reached = numbers(rf"{joint}\s+target\s+(\S+) deg\s+reached\s+(\S+) deg", out)
        assert abs(reached - target) < 1.0, out
    (error,) = numbers(r"error (\S+) mm", out)
    assert error < 5.0, out
    assert compiles_from_disk(tmp_path / "two_link_arm.xml").nu == 2


def test_quadruped_trots_forward(tmp_path: Path) -> None:
    out = run("quadruped.py", tmp_path)
    assert "default classes robot, leg, foot" in out
    forward, sideways = numbers(r"moved (\S+) m forward, (\S+) m sideways", out)
    assert forward > 1.0 and abs(sideways) < 0.5, out
    (tilt,) = numbers(r"lowest cos tilt (\S+)\)", out)
    assert tilt > 0.8, out
    feet = numbers(r"fl (\d+)%, fr (\d+)%, hl (\d+)%, hr (\d+)%", out)
    assert all(20 <= share <= 80 for share in feet), out  # every foot steps, none drags
    (diagonal,) = numbers(r"diagonal pairs alone on the ground: (\d+)%", out)
    assert diagonal > 40, out  # a trot, not a random shuffle
    assert compiles_from_disk(tmp_path / "quadruped.xml").nsensor == 6


def test_arm_gripper_lifts_the_box(tmp_path: Path) -> None:
    out = run("arm_gripper.py", tmp_path)
    assert "arm/gripper/close" in out  # the gripper's actuator, scoped twice by attach
    target = numbers(r"pinch point target \((\S+), (\S+), (\S+)\) m", out)
    reached = numbers(r"reached \((\S+), (\S+), (\S+)\) m", out)
    assert all(abs(r - t) < 0.01 for r, t in zip(reached, target, strict=True)), out
    lifted, distance = numbers(r"lifted (\S+) m\), (\S+) mm from the pinch point", out)
    assert lifted > 0.15 and distance < 20, out
    gap, box = numbers(r"gap between the finger pads (\S+) mm \(box (\S+) mm\)", out)
    assert box - 5 < gap <= box, out  # closed on the box, not through it
    left, right = numbers(r"pads feel (\S+) N and (\S+) N", out)
    assert left > 1 and right > 1, out
    assert compiles_from_disk(tmp_path / "arm_gripper.xml").ntendon == 1


def test_composition_scene_checks_out(tmp_path: Path) -> None:
    out = run("composition_scene.py", tmp_path)
    assert "replicate made 6 pegs: peg_0, peg_1, peg_2, peg_3, peg_4, peg_5" in out
    target, reached = numbers(r"target (\S+) rad, reached (\S+) rad", out)
    assert abs(reached - target) < 0.05, out
    low, high, resting, carried = numbers(
        r"cloth: resting at z (\S+) to (\S+) m \(turntable top \+ vertex radius: (\S+) m\), "
        r"carried round by (\S+) rad", out)
    assert abs(low - resting) < 0.005 and abs(high - resting) < 0.005, out
    assert abs(carried - reached) < 0.05, out  # the cloth turned with the turntable
    for amplitude in (5, 60):
        period, exact = numbers(rf"released at {amplitude} deg, period (\S+) s, exact (\S+) s",
                                out)
        assert abs(period / exact - 1) < 2e-3, out
    # The in-memory pendulum model was written beside the XML, which MuJoCo reads back.
    assert (tmp_path / "pendulum.xml").is_file()
    assert compiles_from_disk(tmp_path / "composition_scene.xml").nflex == 1

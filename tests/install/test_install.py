"""Installing the built wheel never breaks MuJoCo (``nox -s install_matrix``).

Each case makes a fresh virtual environment, installs a MuJoCo release into it, then the
typed-mjcf wheel built from this checkout (pip resolves the dependencies from the package
registry), and checks that ``import mujoco`` works and that typed-mjcf compiles a model with
it. A supported release must be kept as it was (pip must not swap another MuJoCo in); an
unsupported one may be refused by pip or replaced, but ``import mujoco`` must still work.

It downloads and installs several MuJoCo wheels (minutes): it runs only when
``TYPED_MJCF_INSTALL_MATRIX=1`` (``nox -s install_matrix`` sets it), not in ``nox -s tests``.
"""

from __future__ import annotations

import os
import subprocess
import sys
import venv
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
pytestmark = pytest.mark.skipif(
    os.environ.get("TYPED_MJCF_INSTALL_MATRIX") != "1",
    reason="installs MuJoCo releases into fresh environments: nox -s install_matrix")

# what is installed first -> the MuJoCo release `import mujoco` must report afterwards
# (None: unsupported, pip may refuse typed-mjcf or replace MuJoCo, as long as MuJoCo imports)
CASES: dict[str, str | None] = {
    "mujoco==3.3.7": "3.3.7",  # what dm_control 1.0.34 pairs with
    "mujoco==3.17.0": "3.17.0",  # the newest 3.x
    "mujoco==4.0.0": "4.0.0",
    "mujoco-core==4.0.1": None,  # the engine alone: pip adds `mujoco`, which pins its core
    "mujoco==3.2.7": None,  # older than any release typed-mjcf has bindings for
}

# what the new environment runs: MuJoCo imports, typed-mjcf builds and compiles a model
CHECK = """
import mujoco, typed_mjcf
model = typed_mjcf.RootElement(model="m")
body = model.worldbody.add_body(name="b", pos=(0, 0, 1))
body.add_joint(name="j", type="hinge")
body.add_geom(type="sphere", size=(0.1,))
compiled = model.compile()
assert compiled.njnt == 1 and compiled.ngeom == 1, (compiled.njnt, compiled.ngeom)
print(mujoco.__version__)
"""


@pytest.fixture(scope="module")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("wheel")
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(out),
                    str(ROOT)], check=True)
    (built,) = out.glob("typed_mjcf-*.whl")
    return built


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(args, capture_output=True, text=True, check=False)


@pytest.mark.parametrize("first", list(CASES))
def test_installing_typed_mjcf_keeps_mujoco_working(first: str, wheel: Path,
                                                    tmp_path: Path) -> None:
    expected = CASES[first]
    venv.create(tmp_path / "env", with_pip=True)
    python = str(tmp_path / "env" / "bin" / "python")
    prepared = _run(python, "-m", "pip", "install", "-q", first)
    assert prepared.returncode == 0, prepared.stderr
    installed = _run(python, "-m", "pip", "install", "-q", str(wheel))
    imported = _run(python, "-c", "import mujoco; print(mujoco.__version__)")
    assert imported.returncode == 0, (
        f"after installing typed-mjcf over {first}, `import mujoco` fails:\n"
        f"{installed.stdout}{installed.stderr}\n{imported.stderr}")
    if expected is None and installed.returncode != 0:
        return  # refused by pip, MuJoCo untouched
    assert installed.returncode == 0, installed.stderr
    if expected is not None:
        assert imported.stdout.strip() == expected, (
            f"installing typed-mjcf replaced {first} by MuJoCo {imported.stdout.strip()}")
    checked = _run(python, "-c", CHECK)
    assert checked.returncode == 0, checked.stderr
    assert checked.stdout.strip() == imported.stdout.strip()
    assert _run(python, "-m", "pip", "check").returncode == 0

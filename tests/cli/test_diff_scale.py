"""``typed-mjcf diff`` aligns many unnamed siblings in near-linear time (a hang guard, not a
timing test: the command runs in a subprocess that is stopped if it does not finish)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

SITES = 20_000


def test_twenty_thousand_unnamed_siblings(tmp_path: Path) -> None:
    half = "<site/>\n" * (SITES // 2)
    (tmp_path / "a.xml").write_text(f"<mujoco><worldbody>\n{half}{half}</worldbody></mujoco>")
    (tmp_path / "b.xml").write_text(f"<mujoco><worldbody>\n{half}<site pos='1 0 0'/>\n"
                                    f"{half[:-8]}<site size='0.5'/>\n</worldbody></mujoco>")
    run = subprocess.run([sys.executable, "-m", "typed_mjcf", "diff", str(tmp_path / "a.xml"),
                          str(tmp_path / "b.xml")], capture_output=True, text=True,
                         timeout=300, check=False)
    assert run.returncode == 1, run.stderr
    lines = [line for line in run.stdout.splitlines() if line[:2] in ("+ ", "- ", "~ ")]
    added = (f"+ worldbody/site[{SITES // 2}]: <site pos=\"1 0 0\"/>  "
             f"[{tmp_path / 'b.xml'}:{SITES // 2 + 2}]")
    changed = (f"~ worldbody/site[{SITES}]: size (unset) -> \"0.5\"  "
               f"[{tmp_path / 'a.xml'}:{SITES + 1}, {tmp_path / 'b.xml'}:{SITES + 2}]")
    assert lines == [added, changed]

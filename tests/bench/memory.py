"""What loading costs in memory, per kind of text: ``python -m tests.bench.memory [SIZE_MB]``.

Each case runs in a fresh interpreter: the text is built, then read (``from_xml_string``),
and the growth of the peak resident size (``ru_maxrss``) is printed beside the text's size.
Two shapes of text: one long number list (a mesh's vertices) and many elements (``<geom>``s,
each with a size). Linux only (``ru_maxrss`` in KiB).
"""

from __future__ import annotations

import subprocess
import sys
import textwrap

_CHILD = """
    import resource
    import typed_mjcf as mjcf

    megabytes = {megabytes}
    if {kind!r} == "numbers":
        body = "0.125 -7 1e-3 " * (megabytes * 1_000_000 // 14)
        xml = '<mujoco><asset><mesh name="m" vertex="' + body + '"/></asset></mujoco>'
    else:
        geom = '<geom size="0.1"/>'
        count = min(megabytes * 1_000_000 // len(geom), mjcf.ParseLimits().max_elements - 3)
        xml = "<mujoco><worldbody><body>" + geom * count + "</body></worldbody></mujoco>"
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    model = mjcf.from_xml_string(xml)
    after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    print(len(xml), (after - before) * 1024)
"""


def measure(kind: str, megabytes: int) -> tuple[int, int]:
    """(bytes of text, bytes the load added to the peak resident size)."""
    code = textwrap.dedent(_CHILD.format(kind=kind, megabytes=megabytes))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=True)
    text, grown = done.stdout.split()
    return int(text), int(grown)


def main(argv: list[str]) -> int:
    megabytes = int(argv[0]) if argv else 20
    print(f"{'text':<40} {'MB':>8} {'load MB':>9} {'x text':>7}")
    for kind, label in (("numbers", "one number list (mesh vertex)"),
                        ("elements", "many elements (<geom size=...>)")):
        text, grown = measure(kind, megabytes)
        print(f"{label:<40} {text / 1e6:8.1f} {grown / 1e6:9.1f} {grown / text:7.1f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
